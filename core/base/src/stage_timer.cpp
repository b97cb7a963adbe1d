#include "strahler/base/stage_timer.h"

namespace strahler::base {

void StageTimer::start(std::string_view stage) {
  finish();
  stages_.push_back({std::string(stage), 0.0});
  begin_ = Clock::now();
  running_ = true;
}

void StageTimer::finish() {
  if (!running_)
    return;
  stages_.back().seconds = std::chrono::duration<double>(Clock::now() - begin_).count();
  running_ = false;
}

} // namespace strahler::base
