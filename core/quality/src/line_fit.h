#pragma once

#include <cstddef>
#include <limits>
#include <span>

namespace strahler::quality::detail {

/// A least-squares line y = intercept + slope · x.
struct LineFit {
  double slope = std::numeric_limits<double>::quiet_NaN();
  double intercept = std::numeric_limits<double>::quiet_NaN();
  /// Coefficient of determination; 1 where y does not vary.
  double r2 = std::numeric_limits<double>::quiet_NaN();
};

/// The least-squares line through (x[i], y[i]) (same sizes); every field NaN with fewer than
/// two points or no spread in x. Means first, then centred sums (one order for every figure
/// that fits a line: Horton's ratios, slope–area θ, Hack's h, the spectral slope).
LineFit fitLine(std::span<const double> x, std::span<const double> y) noexcept;

} // namespace strahler::quality::detail
