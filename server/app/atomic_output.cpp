#include "atomic_output.h"

#include <atomic>
#include <cstdio>
#include <fcntl.h>
#include <filesystem>
#include <unistd.h>

namespace strahler::app {

using base::ErrorCode;
using base::makeError;
namespace fs = std::filesystem;

base::Status checkWritable(const std::string& output) {
  const fs::path path(output);
  const fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
  std::error_code ec;
  if (fs::is_directory(path, ec))
    return makeError(ErrorCode::kIoError, "cannot write '" + output + "': it is a folder");
  if (!fs::is_directory(folder, ec))
    return makeError(ErrorCode::kIoError,
                     "cannot write '" + output + "': no folder '" + folder.string() + "'");
  if (::access(folder.c_str(), W_OK) != 0)
    return makeError(ErrorCode::kIoError, "cannot write '" + output + "': folder '" +
                                              folder.string() + "' is not writable");
  return base::Ok{};
}

namespace {

std::atomic<int> gSignal{0};

extern "C" void noteSignal(int signal) {
  gSignal.store(signal);
}

} // namespace

int caughtSignal() noexcept {
  return gSignal.load();
}

void clearCaughtSignal() noexcept {
  gSignal.store(0);
}

SignalCatcher::SignalCatcher() {
  struct sigaction action = {};
  action.sa_handler = noteSignal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, &oldInt_);
  sigaction(SIGTERM, &action, &oldTerm_);
}

SignalCatcher::~SignalCatcher() {
  sigaction(SIGINT, &oldInt_, nullptr);
  sigaction(SIGTERM, &oldTerm_, nullptr);
}

TemporaryOutput::TemporaryOutput(std::string final)
    : final_(std::move(final)), path_(final_ + ".tmp." + std::to_string(::getpid())) {
  std::error_code ignored;
  fs::remove(path_, ignored);
}

base::Status TemporaryOutput::commit() {
  // The data reaches the disk before the name does (SQLite runs with synchronous = OFF).
  if (const int fd = ::open(path_.c_str(), O_RDONLY | O_CLOEXEC); fd >= 0) {
    ::fsync(fd);
    ::close(fd);
  }
  std::error_code ec;
  fs::rename(path_, final_, ec);
  if (ec)
    return makeError(ErrorCode::kIoError, "cannot write '" + final_ + "': " + ec.message());
  committed_ = true;
  return base::Ok{};
}

void TemporaryOutput::discard() {
  if (committed_)
    return;
  std::error_code ignored;
  fs::remove(path_, ignored);
  committed_ = true;
}

std::string formatSeconds(double s) {
  char text[32];
  if (s < 60)
    std::snprintf(text, sizeof text, "%.0fs", s);
  else if (s < 3600)
    std::snprintf(text, sizeof text, "%dm%02ds", static_cast<int>(s / 60),
                  static_cast<int>(s) % 60);
  else
    std::snprintf(text, sizeof text, "%dh%02dm", static_cast<int>(s / 3600),
                  static_cast<int>(s / 60) % 60);
  return text;
}

int dieBy(int signal) {
  std::signal(signal, SIG_DFL);
  std::raise(signal);
  return 128 + signal;
}

} // namespace strahler::app
