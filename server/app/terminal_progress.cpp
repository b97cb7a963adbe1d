#include "terminal_progress.h"

#include <cstdio>
#include <unistd.h>

namespace strahler::app {

TerminalProgress::TerminalProgress(bool quiet) : enabled_(!quiet && isatty(STDERR_FILENO) == 1) {}

TerminalProgress::~TerminalProgress() {
  endLine();
}

base::ProgressCallback TerminalProgress::callback() {
  return [this](std::string_view stage, double fraction) { report(stage, fraction); };
}

void TerminalProgress::report(std::string_view stage, double fraction) {
  if (!enabled_)
    return;
  if (stage != stage_) {
    endLine();
    stage_ = stage;
    lastPercent_ = -1;
  }
  const int percent = static_cast<int>(fraction * 100.0);
  if (percent == lastPercent_)
    return;
  lastPercent_ = percent;
  std::fprintf(stderr, "\r  %-10s %3d%%", stage_.c_str(), percent);
  std::fflush(stderr);
}

void TerminalProgress::update(std::string_view stage, double fraction, std::string_view detail) {
  if (!enabled_)
    return;
  if (stage != stage_) {
    endLine();
    stage_ = stage;
  }
  lastPercent_ = static_cast<int>(fraction * 100.0);
  // \x1b[K clears what a longer previous line left.
  std::fprintf(stderr, "\r  %-10s %3d%% %.*s\x1b[K", stage_.c_str(), lastPercent_,
               static_cast<int>(detail.size()), detail.data());
  std::fflush(stderr);
}

void TerminalProgress::endLine() {
  if (enabled_ && !stage_.empty())
    std::fputc('\n', stderr);
  stage_.clear();
}

} // namespace strahler::app
