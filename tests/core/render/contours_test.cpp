// Contours by marching squares: a cone's isolines are circles, a plane's are straight lines,
// and two grids that share a column of samples cross it at the same points.
#include "strahler/render/contours.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace strahler::render {
namespace {

/// A cone of height 100 at (cx, cy), 1 m per grid unit: h = 100 − r.
std::vector<double> cone(int n, double cx, double cy) {
  std::vector<double> h;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      h.push_back(100.0 - std::hypot(i - cx, j - cy));
  return h;
}

TEST(Contours, LevelsAreTheMultiplesOfTheIntervalInTheRange) {
  EXPECT_EQ(contourLevels(-3.0, 55.0, 20.0), (std::vector<double>{0.0, 20.0, 40.0}));
  EXPECT_EQ(contourLevels(20.0, 40.0, 20.0), (std::vector<double>{40.0}));
  EXPECT_TRUE(contourLevels(1.0, 19.0, 20.0).empty());
}

TEST(Contours, AConesIsolinesAreClosedCircles) {
  const int n = 101;
  const std::vector<double> h = cone(n, 50.3, 49.6);
  const std::vector<double> levels = {60.0, 80.0, 95.0};
  const std::vector<ContourLine> lines = traceContours(h, n, n, levels);
  ASSERT_EQ(lines.size(), 3u);
  for (const ContourLine& line : lines) {
    EXPECT_TRUE(line.closed) << line.elevation;
    const double radius = 100.0 - line.elevation;
    // A circle of radius r crosses about 4·2r grid edges.
    EXPECT_GT(line.points.size(), static_cast<std::size_t>(6.0 * radius));
    for (const geometry::Vec2 p : line.points)
      EXPECT_NEAR(std::hypot(p.x - 50.3, p.y - 49.6), radius, 0.05) << line.elevation;
  }
}

TEST(Contours, APlanesIsolineIsOneOpenLineAcrossTheGrid) {
  const int w = 20, rows = 10;
  std::vector<double> h;
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < w; ++i)
      h.push_back(2.0 * i + 0.1 * j); // rising east
  const std::vector<ContourLine> lines = traceContours(h, w, rows, std::vector<double>{15.0});
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_FALSE(lines[0].closed);
  ASSERT_EQ(lines[0].points.size(), static_cast<std::size_t>(rows));
  for (const geometry::Vec2 p : lines[0].points)
    EXPECT_NEAR(2.0 * p.x + 0.1 * p.y, 15.0, 1e-9);
}

TEST(Contours, NeighbouringGridsCrossTheirSharedColumnAtTheSamePoints) {
  // Two halves of one cone that share column 50: their lines cross it at the same rows.
  const int n = 101, half = 51;
  const std::vector<double> h = cone(n, 47.2, 50.4);
  std::vector<double> west, east;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < half; ++i)
      west.push_back(h[static_cast<std::size_t>(j * n + i)]);
    for (int i = half - 1; i < n; ++i)
      east.push_back(h[static_cast<std::size_t>(j * n + i)]);
  }
  const std::vector<double> levels = {70.0};
  const auto crossings = [](const std::vector<ContourLine>& lines, double column) {
    std::vector<double> rows;
    for (const ContourLine& line : lines)
      for (const geometry::Vec2 p : line.points)
        if (p.x == column)
          rows.push_back(p.y);
    std::sort(rows.begin(), rows.end());
    return rows;
  };
  const auto w = crossings(traceContours(west, half, n, levels), half - 1.0);
  const auto e = crossings(traceContours(east, n - half + 1, n, levels), 0.0);
  ASSERT_EQ(w.size(), 2u);
  EXPECT_EQ(w, e);
}

} // namespace
} // namespace strahler::render
