#include "strahler/quality/relief.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace strahler::quality {
namespace {

constexpr double kPi = 3.141592653589793;

/// An all-land raster of `width` x `height` cells of `cellSize` metres with heights z(x, y)
/// (x, y in metres from cell (0, 0)).
HeightRaster makeRaster(int width, int height, double cellSize,
                        const std::function<double(double, double)>& z) {
  HeightRaster r;
  r.width = width;
  r.height = height;
  r.cellSize = cellSize;
  r.heights.resize(std::size_t(width) * std::size_t(height));
  r.cellClass.assign(r.heights.size(), std::uint8_t(CellClass::kLand));
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      r.heights[std::size_t(y) * std::size_t(width) + std::size_t(x)] =
          float(z(x * cellSize, y * cellSize));
  return r;
}

constexpr int kValleys = 4;
constexpr int kValleyRows = 41; // the axis in the middle row, ridges between valleys
constexpr int kValleyLength = 600;
constexpr double kValleyCell = 30.0;

/// Parallel V-shaped valleys draining to x = 0, whose channels follow S = k·A^-θ exactly
/// for the area each channel cell drains (its valley's width times the columns upstream).
HeightRaster makeValleys(double theta) {
  const double cellKm2 = kValleyCell * kValleyCell * 1e-6;
  std::vector<double> channel(kValleyLength, 10.0);
  for (int x = 1; x < kValleyLength; ++x) {
    const double area = kValleyRows * double(kValleyLength - x) * cellKm2;
    channel[std::size_t(x)] =
        channel[std::size_t(x - 1)] + 0.02 * std::pow(area, -theta) * kValleyCell;
  }
  return makeRaster(kValleyLength, kValleys * kValleyRows, kValleyCell, [&](double x, double y) {
    const int row = int(std::lround(y / kValleyCell));
    const int offset = std::abs(row % kValleyRows - kValleyRows / 2);
    return channel[std::size_t(std::lround(x / kValleyCell))] + 0.3 * offset * kValleyCell;
  });
}

TEST(Relief, APlaneHasOneSlopeNoChannelsAndNoDissection) {
  const double gradient = 0.1;
  const HeightRaster plane =
      makeRaster(400, 400, 30.0, [&](double x, double y) { return 100 + gradient * x + 0 * y; });
  const ReliefFigures figures = measureRelief(plane);
  const double degrees = std::atan(gradient) * 180.0 / kPi;
  EXPECT_NEAR(figures.slopes.p50Deg, degrees, 1e-3);
  EXPECT_NEAR(figures.slopes.p90Deg, degrees, 1e-3);
  EXPECT_NEAR(figures.slopes.p99Deg, degrees, 1e-3);
  EXPECT_EQ(figures.slopes.cells, 398u * 398u);
  EXPECT_EQ(figures.slopes.steeperThan45, 0.0);
  // Parallel flow: no cell drains 1 km², so there is nothing to fit.
  EXPECT_TRUE(std::isnan(figures.slopeArea.theta));
  EXPECT_TRUE(std::isnan(figures.slopeArea.r2));
  EXPECT_EQ(figures.slopeArea.bins, 0u);
  EXPECT_EQ(figures.confluences.confluences, 0u);
  EXPECT_TRUE(std::isnan(figures.confluences.shareThreeOrMore));
  EXPECT_EQ(figures.drainageDensity1, 0.0);
  // Smoothing keeps a plane's slope, but for the kernel truncated by the raster's edge: at
  // 2–3σ from it the normalised kernel's centre shifts inward, flattening the smoothed plane.
  EXPECT_NEAR(figures.dissection, 1.0, 0.03);
  EXPECT_EQ(figures.landCells, 400u * 400u);
}

TEST(Relief, SteepPlanesCountAsSteeperThan45Degrees) {
  const HeightRaster plane = makeRaster(20, 20, 10.0, [](double x, double y) { return x + y; });
  const SlopeStatistics stats = measureSlopes(plane);
  EXPECT_NEAR(stats.p50Deg, std::atan(std::sqrt(2.0)) * 180.0 / kPi, 1e-3);
  EXPECT_EQ(stats.steeperThan45, 1.0);
}

TEST(Relief, ValleysWithAPowerLawProfileGiveTheirConcavity) {
  for (const double theta : {0.3, 0.5}) {
    const HeightRaster valleys = makeValleys(theta);
    const FlowField flow = computeFlowField(valleys);
    const SlopeAreaFit fit = fitSlopeArea(valleys, flow);
    EXPECT_NEAR(fit.theta, theta, 0.03) << theta;
    EXPECT_GT(fit.r2, 0.99) << theta;
    EXPECT_GE(fit.bins, 5u) << theta;
  }
}

TEST(Relief, ValleysDrainToTheirAxesAndHaveNoConfluences) {
  const HeightRaster valleys = makeValleys(0.5);
  const FlowField flow = computeFlowField(valleys);
  // The border cells are outlets, so the outlet of an inner valley drains all of it but its
  // first and last columns, plus itself.
  const double cellKm2 = kValleyCell * kValleyCell * 1e-6;
  const std::size_t outlet =
      std::size_t(kValleyRows + kValleyRows / 2) * std::size_t(kValleyLength);
  EXPECT_NEAR(flow.areaKm2[outlet], (kValleyRows * (kValleyLength - 2) + 1) * cellKm2, 1e-6);
  EXPECT_EQ(flow.receiver[outlet], FlowField::kNone);
  EXPECT_EQ(flow.receiver[outlet + 1], outlet);
  EXPECT_EQ(flow.receiver[outlet + kValleyLength + 1], outlet + 1) << "hillslopes go straight down";
  const ConfluenceCount count = countConfluences(flow);
  EXPECT_EQ(count.confluences, 0u);
  // Channels ≥ 1 km²: the axis cells with ≥ 28 columns of 40 or 41 cells upstream
  // (40·28·0.0009 km² ≥ 1), up to the outlet, each one cell long.
  const int upstreamColumns = int(std::ceil(1.0 / ((kValleyRows - 1) * cellKm2)));
  const double channelKm = kValleys * double(kValleyLength - upstreamColumns) * kValleyCell * 1e-3;
  const double landKm2 = double(valleys.heights.size()) * cellKm2;
  EXPECT_NEAR(drainageDensity(flow, 1.0), channelKm / landKm2, 1e-9);
  EXPECT_GT(drainageDensity(flow, 0.1), drainageDensity(flow, 1.0));
}

/// A hand-made flow field over a w x h raster of 100 m cells: receivers and areas given.
FlowField makeFlow(int w, int h, const std::vector<std::pair<int, int>>& edges,
                   const std::vector<double>& area) {
  FlowField flow;
  flow.width = w;
  flow.height = h;
  flow.cellSize = 100.0;
  flow.filled.assign(std::size_t(w * h), 0.0f);
  flow.receiver.assign(std::size_t(w * h), FlowField::kNone);
  flow.areaKm2 = area;
  for (const auto& [from, to] : edges)
    flow.receiver[std::size_t(from)] = std::uint32_t(to);
  for (int c = 0; c < w * h; ++c)
    flow.order.push_back(std::uint32_t(c)); // order only matters for accumulation
  return flow;
}

TEST(Relief, AThreeWayConfluenceIsCounted) {
  // 5 x 5 cells, index y * 5 + x. Cell 12 (centre) takes channels from 11, 13 and 17; cell 2
  // takes channels from 1 and 3; cell 7 takes one channel (2) and a small stream (6).
  std::vector<double> area(25, 0.01);
  for (int c : {11, 13, 17, 1, 3})
    area[std::size_t(c)] = 2.0;
  area[2] = 4.5, area[7] = 4.6, area[12] = 11.2;
  const FlowField flow =
      makeFlow(5, 5, {{11, 12}, {13, 12}, {17, 12}, {1, 2}, {3, 2}, {2, 7}, {6, 7}, {7, 12}}, area);
  const ConfluenceCount count = countConfluences(flow, 1.0);
  EXPECT_EQ(count.confluences, 2u); // 12 (four inflows: 7, 11, 13, 17) and 2
  EXPECT_EQ(count.threeOrMore, 1u);
  EXPECT_DOUBLE_EQ(count.shareThreeOrMore, 0.5);
}

TEST(Relief, DissectionOfRipplesOnAPlaneIsTheirMedianSlopeOverThePlanes) {
  // A plane rising north (gradient g) with ripples along x (amplitude a, wavelength λ): the
  // σ = 1 km Gaussian removes the ripples, leaving g; the central difference of a sine of
  // wavenumber k has amplitude a·sin(k·c)/c, so the raw slope at x is
  // sqrt(g² + (a·sin(k·c)/c · cos(k·x))²).
  const double g = 0.05, a = 20.0, lambda = 317.0, cell = 30.0, k = 2 * kPi / lambda;
  const int n = 400;
  const HeightRaster raster =
      makeRaster(n, n, cell, [&](double x, double y) { return 500 + g * y + a * std::sin(k * x); });
  std::vector<double> slopes;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const int edge = std::min(std::min(x, n - 1 - x), std::min(y, n - 1 - y));
      if ((edge + 0.5) * cell <= 2000.0)
        continue;
      const double b = a * std::sin(k * cell) / cell * std::cos(k * x * cell);
      slopes.push_back(std::sqrt(g * g + b * b));
    }
  std::sort(slopes.begin(), slopes.end());
  const double median = 0.5 * (slopes[(slopes.size() - 1) / 2] + slopes[slopes.size() / 2]);
  EXPECT_NEAR(measureDissection(raster), median / g, 0.03 * median / g); // edge: see the plane
}

TEST(Relief, DissectionAroundAGaussianBumpExceedsOne) {
  // A 150 m wide bump on a plane: the smoothed bump is nearly gone, so the median slope
  // (mostly the plane's) over the smoothed mean stays near 1, and above it.
  const double g = 0.05;
  const HeightRaster raster = makeRaster(200, 200, 30.0, [&](double x, double y) {
    const double dx = x - 3000, dy = y - 3000;
    return 100 + g * x + 50 * std::exp(-(dx * dx + dy * dy) / (2 * 150.0 * 150.0));
  });
  const double dissection = measureDissection(raster);
  EXPECT_GT(dissection, 1.0);
  EXPECT_LT(dissection, 1.2);
}

TEST(Relief, NoInteriorCellMeansNoDissection) {
  HeightRaster island = makeRaster(100, 100, 30.0, [](double x, double) { return x * 0.1; });
  EXPECT_TRUE(std::isnan(measureDissection(island))) << "3 km wide: nothing 2 km from the edge";
  HeightRaster sea = makeRaster(200, 200, 30.0, [](double x, double) { return x * 0.1; });
  for (std::size_t i = 0; i < sea.cellClass.size(); i += 50)
    sea.cellClass[i] = std::uint8_t(CellClass::kSea);
  EXPECT_TRUE(std::isnan(measureDissection(sea)));
}

TEST(Relief, PitsAreFilledSoEveryLandCellReachesAnOutlet) {
  // A bowl: without filling its bottom would be a pit.
  const HeightRaster bowl = makeRaster(41, 41, 10.0, [](double x, double y) {
    return std::hypot(x - 200, y - 200) < 100 ? 1.0 : 5.0 + 0.01 * x;
  });
  const FlowField flow = computeFlowField(bowl);
  double outletArea = 0;
  for (std::uint32_t c : flow.order)
    if (flow.receiver[c] == FlowField::kNone)
      outletArea += flow.areaKm2[c];
  EXPECT_NEAR(outletArea, 41 * 41 * 1e-4, 1e-9);
}

} // namespace
} // namespace strahler::quality
