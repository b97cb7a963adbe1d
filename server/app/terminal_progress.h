#pragma once

#include "strahler/base/stage_timer.h"

#include <string>

namespace strahler::app {

/// Progress reporting on stderr: a live percentage per stage on a terminal, nothing when
/// stderr is redirected (logs stay clean) or when quiet.
class TerminalProgress {
public:
  /// Reporter; silent when `quiet` or when stderr is not a terminal.
  explicit TerminalProgress(bool quiet);
  ~TerminalProgress();

  /// The callback to hand to the pipeline.
  base::ProgressCallback callback();
  /// Shows `stage` at `fraction` (0..1) followed by `detail` (counts, ETA); callers throttle.
  void update(std::string_view stage, double fraction, std::string_view detail);
  /// True when it prints at all.
  bool enabled() const noexcept { return enabled_; }

private:
  void report(std::string_view stage, double fraction);
  void endLine();

  bool enabled_;
  std::string stage_;
  int lastPercent_ = -1;
};

} // namespace strahler::app
