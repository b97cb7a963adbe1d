#pragma once

#include <chrono>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace strahler::base {

/// Reports progress of a long computation: stage name and fraction done in [0, 1].
using ProgressCallback = std::function<void(std::string_view stage, double fraction)>;

/// Wall time spent in one named stage.
struct StageTime {
  std::string stage;
  double seconds = 0.0;
};

/// Measures consecutive stages: start("network"), start("blocks"), ..., finish().
class StageTimer {
public:
  /// Ends the running stage (if any) and starts `stage`.
  void start(std::string_view stage);
  /// Ends the running stage.
  void finish();
  /// Every finished stage, in order.
  const std::vector<StageTime>& stages() const noexcept { return stages_; }

private:
  using Clock = std::chrono::steady_clock;
  std::vector<StageTime> stages_;
  Clock::time_point begin_{};
  bool running_ = false;
};

} // namespace strahler::base
