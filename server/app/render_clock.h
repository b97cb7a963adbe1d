#pragma once

#include <chrono>

namespace strahler::app {

/// The clock renderers time their steps with (RenderedTile's evaluateMs and encodeMs).
using RenderClock = std::chrono::steady_clock;

/// Milliseconds from `start` to now.
inline double millisecondsSince(RenderClock::time_point start) {
  return std::chrono::duration<double, std::milli>(RenderClock::now() - start).count();
}

} // namespace strahler::app
