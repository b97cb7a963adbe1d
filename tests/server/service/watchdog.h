#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <string>
#include <thread>

namespace strahler::service::test_support {

/// Bounds the time of a concurrency test: aborts the process with a message when the scope
/// is not left within `limit`, so that a deadlock fails fast instead of hanging the suite.
class Watchdog {
public:
  explicit Watchdog(std::string what,
                    std::chrono::milliseconds limit = std::chrono::milliseconds(20000))
      : what_(std::move(what)), thread_([this, limit] { watch(limit); }) {}
  Watchdog(const Watchdog&) = delete;
  Watchdog& operator=(const Watchdog&) = delete;
  ~Watchdog() {
    {
      std::lock_guard lock(mutex_);
      done_ = true;
    }
    doneChanged_.notify_all();
    thread_.join();
  }

private:
  void watch(std::chrono::milliseconds limit) {
    std::unique_lock lock(mutex_);
    if (!doneChanged_.wait_for(lock, limit, [this] { return done_; })) {
      std::fprintf(stderr, "watchdog: '%s' did not finish in %lld ms (deadlock?)\n", what_.c_str(),
                   static_cast<long long>(limit.count()));
      std::abort();
    }
  }

  std::string what_;
  std::mutex mutex_;
  std::condition_variable doneChanged_;
  bool done_ = false;
  std::thread thread_;
};

} // namespace strahler::service::test_support
