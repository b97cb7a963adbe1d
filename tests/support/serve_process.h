#pragma once

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <sys/types.h>
#include <vector>

namespace strahler::test_support {

/// `strahler serve` (or any program) as a child of the test, so its exit status can be read;
/// its stdout is piped to the test. Killed (SIGKILL) and reaped on destruction if still running.
class ServeProcess {
public:
  using Clock = std::chrono::steady_clock;

  /// Starts `args` (args[0] the executable) with `extraEnvironment` ("NAME=value") added to the
  /// test's environment.
  ServeProcess(const std::vector<std::string>& args, const std::string& extraEnvironment);
  ~ServeProcess();
  ServeProcess(const ServeProcess&) = delete;
  ServeProcess& operator=(const ServeProcess&) = delete;

  /// The child's process id; -1 when it could not be started or has been reaped.
  pid_t pid() const noexcept { return pid_; }
  /// The next line of stdout (without the newline); empty at end of file.
  std::string readLine() const;
  /// Reads serve's banner ("... http://127.0.0.1:PORT") and returns the port; 0 (and the line
  /// in `banner`) when the first line is not one.
  std::uint16_t readPort(std::string* banner = nullptr) const;
  /// Waits until the process exits or `deadline` passes; its wait status, or nothing.
  std::optional<int> waitUntil(Clock::time_point deadline);
  /// The process's resident memory (VmRSS) in MB; -1 when unknown.
  long residentMb() const;

private:
  pid_t pid_ = -1;
  std::FILE* out_ = nullptr;
};

} // namespace strahler::test_support
