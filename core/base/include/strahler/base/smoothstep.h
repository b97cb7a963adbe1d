#pragma once

#include <algorithm>

namespace strahler::base {

/// 3t² − 2t³ of t clamped to [0, 1]: 0 below 0, 1 above 1, flat at both ends. The one
/// spelling of it, so every stage that fades with it gets the same bits.
constexpr double smoothstep(double t) noexcept {
  t = std::clamp(t, 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

} // namespace strahler::base
