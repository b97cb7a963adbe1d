#include "strahler/quality/river_profile.h"

#include "strahler/base/assert.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace strahler::quality {
namespace {

using geometry::Vec2;

double polylineLength(const std::vector<Vec2>& line) {
  double total = 0.0;
  for (std::size_t i = 0; i + 1 < line.size(); ++i)
    total += geometry::distance(line[i], line[i + 1]);
  return total;
}

/// Calls visit(point) at arc lengths 0, spacing, 2 spacing, ... along `line`, then at its end
/// unless the last regular sample is already there (within a relative 1e-9, so rounding never
/// doubles the end sample). Arc lengths are j * spacing, not a running sum, so they do not drift.
template <class Visit>
void sampleAlong(const std::vector<Vec2>& line, double spacing, Visit&& visit) {
  if (line.empty())
    return;
  constexpr double kSlack = 1e-9;
  const double total = polylineLength(line);
  const auto regular = static_cast<std::size_t>(std::floor(total / spacing + kSlack));
  const bool extraEnd = total - double(regular) * spacing > kSlack * spacing;
  std::size_t segment = 0;
  double segmentStart = 0.0;
  for (std::size_t j = 0; j <= regular + (extraEnd ? 1 : 0); ++j) {
    const double arc = std::min(double(j) * spacing, total);
    double length =
        segment + 1 < line.size() ? geometry::distance(line[segment], line[segment + 1]) : 0.0;
    while (segment + 2 < line.size() && segmentStart + length < arc) {
      segmentStart += length;
      ++segment;
      length = geometry::distance(line[segment], line[segment + 1]);
    }
    if (length <= 0.0) {
      visit(line[segment]);
      continue;
    }
    visit(geometry::lerp(line[segment], line[segment + 1],
                         std::clamp((arc - segmentStart) / length, 0.0, 1.0)));
  }
}

/// Samples one centreline into `report`.
void checkCentreline(const std::vector<Vec2>& line, const std::function<double(Vec2)>& height,
                     double spacing, double tolerance, RiverProfileReport& report) {
  double lowest = INFINITY;
  sampleAlong(line, spacing, [&](Vec2 p) {
    const double h = height(p);
    ++report.samples;
    const double rise = h - lowest;
    if (rise > tolerance) {
      ++report.violations;
      if (rise > report.worstRise) {
        report.worstRise = rise;
        report.worstAt = p;
      }
    }
    lowest = std::min(lowest, h);
  });
}

} // namespace

RiverProfileReport checkRiversDescend(const std::vector<std::vector<Vec2>>& centrelines,
                                      const std::function<double(Vec2)>& height,
                                      double sampleSpacing, double tolerance) {
  STRAHLER_ASSERT(sampleSpacing > 0.0 && std::isfinite(sampleSpacing),
                  "sample spacing must be positive");
  RiverProfileReport report;
  for (const std::vector<Vec2>& line : centrelines)
    checkCentreline(line, height, sampleSpacing, tolerance, report);
  return report;
}

} // namespace strahler::quality
