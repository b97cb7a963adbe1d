#pragma once
// What the exporting commands share: output checks, a file that only appears when complete
// (temporary + rename), SIGINT/SIGTERM caught while exporting, and the ETA's text.

#include "strahler/base/result.h"

#include <csignal>
#include <string>

namespace strahler::app {

/// kIoError naming `output` when its folder is missing or not writable, or it is a folder.
base::Status checkWritable(const std::string& output);

/// The SIGINT or SIGTERM caught by a live SignalCatcher since clearCaughtSignal(), else 0.
int caughtSignal() noexcept;
/// Forgets any caught signal (before an export starts).
void clearCaughtSignal() noexcept;

/// While alive, SIGINT and SIGTERM only set caughtSignal() (the export stops at its next step
/// and cleans up); the previous handlers come back after.
class SignalCatcher {
public:
  SignalCatcher();
  ~SignalCatcher();
  SignalCatcher(const SignalCatcher&) = delete;
  SignalCatcher& operator=(const SignalCatcher&) = delete;

private:
  struct sigaction oldInt_ = {};
  struct sigaction oldTerm_ = {};
};

/// FILE.tmp.PID beside FILE: removed when destroyed unless commit() renamed it to FILE.
class TemporaryOutput {
public:
  /// The temporary name of `final` (an old one of this process is removed).
  explicit TemporaryOutput(std::string final);
  ~TemporaryOutput() { discard(); }
  TemporaryOutput(const TemporaryOutput&) = delete;
  TemporaryOutput& operator=(const TemporaryOutput&) = delete;

  /// The temporary file's path.
  const std::string& path() const noexcept { return path_; }
  /// Syncs the file and renames it to its final name.
  base::Status commit();
  /// Removes the file now (before dying by a signal, when no destructor runs).
  void discard();

private:
  std::string final_;
  std::string path_;
  bool committed_ = false;
};

/// "42s", "3m07s" or "2h05m".
std::string formatSeconds(double s);

/// Dies by `signal` as if never caught (the shell sees 128 + signal); returns if it cannot.
int dieBy(int signal);

} // namespace strahler::app
