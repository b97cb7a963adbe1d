#include "strahler/quality/river_agreement.h"

#include "d8_grid.h"

#include "strahler/geometry/distance_transform.h"
#include "strahler/quality/world_raster.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace strahler::quality {
namespace {

using geometry::Vec2;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// The raster cell holding p, or -1 outside the raster.
long cellAt(const HeightRaster& r, Vec2 p) {
  const long x = std::lround((p.x - r.origin.x) / r.cellSize);
  const long y = std::lround((p.y - r.origin.y) / r.cellSize);
  if (x < 0 || y < 0 || x >= r.width || y >= r.height)
    return -1;
  return y * long(r.width) + x;
}

/// Calls fn(point, length) for pieces of the polyline at most half a cell long (midpoints).
template <class Fn> void walkPolyline(const std::vector<Vec2>& line, double cellSize, Fn&& fn) {
  for (std::size_t k = 0; k + 1 < line.size(); ++k) {
    const Vec2 a = line[k], b = line[k + 1];
    const double length = distance(a, b);
    const int steps = std::max(1, int(std::ceil(length / (0.5 * cellSize))));
    for (int j = 0; j < steps; ++j)
      fn(lerp(a, b, (j + 0.5) / steps), length / steps);
  }
}

/// Distance (m) from every cell to the nearest cell a river centreline crosses.
std::vector<float> distanceToRivers(const construction::World& world, const HeightRaster& r) {
  std::vector<std::uint8_t> onRiver(r.heights.size(), 0);
  for (const std::vector<Vec2>& line : riverCentrelines(world))
    walkPolyline(line, r.cellSize, [&](Vec2 p, double) {
      if (const long c = cellAt(r, p); c >= 0)
        onRiver[std::size_t(c)] = 1;
    });
  return geometry::distanceToMarked(r.width, r.height, r.cellSize, onRiver);
}

double channelsNearRivers(const std::vector<float>& distance, const FlowField& flow) {
  std::size_t channels = 0, near = 0;
  for (std::uint32_t c : flow.order)
    if (flow.areaKm2[c] >= kChannelAreaKm2) {
      ++channels;
      near += distance[c] <= kAgreementDistanceM ? 1 : 0;
    }
  return channels == 0 ? kNaN : double(near) / double(channels);
}

/// How near the rivers come to every land cell: the 99th percentile and the greatest distance
/// (m), and the share of land cells farther than kCoverageDistanceM.
void measureCoverage(const std::vector<float>& distance, const HeightRaster& r,
                     NetworkReliefFigures& figures) {
  std::vector<float> land;
  std::size_t farthest = distance.size(); // none yet
  for (std::size_t c = 0; c < distance.size(); ++c)
    if (d8::isLand(r, c)) {
      land.push_back(distance[c]);
      if (farthest == distance.size() || distance[c] > distance[farthest])
        farthest = c;
    }
  if (land.empty())
    return;
  const auto row = static_cast<double>(farthest / std::size_t(r.width));
  const auto column = static_cast<double>(farthest % std::size_t(r.width));
  figures.farthestFromRivers = r.origin + Vec2{column, row} * r.cellSize;
  const auto p99 = land.begin() + static_cast<std::ptrdiff_t>(0.99 * double(land.size() - 1));
  std::nth_element(land.begin(), p99, land.end());
  figures.riverDistanceP99M = *p99;
  figures.riverDistanceMaxM = *std::max_element(p99, land.end());
  const auto far =
      std::count_if(land.begin(), land.end(), [](float d) { return d > kCoverageDistanceM; });
  figures.fartherThanCoverageFraction = double(far) / double(land.size());
}

double riversNearChannels(const construction::World& world, const HeightRaster& r,
                          const FlowField& flow) {
  std::vector<std::uint8_t> channel(r.heights.size(), 0);
  for (std::uint32_t c : flow.order)
    channel[c] = flow.areaKm2[c] >= kChannelAreaKm2 ? 1 : 0;
  const std::vector<float> distance =
      geometry::distanceToMarked(r.width, r.height, r.cellSize, channel);
  double total = 0.0, near = 0.0;
  for (const primitives::RiverPrimitive& river : world.data().rivers) {
    if (world.data().network.node(river.node).strahler < 2)
      continue;
    walkPolyline(riverCentreline(world, river), r.cellSize, [&](Vec2 p, double length) {
      total += length;
      const long c = cellAt(r, p);
      near += c >= 0 && distance[std::size_t(c)] <= kAgreementDistanceM ? length : 0.0;
    });
  }
  return total > 0 ? near / total : kNaN;
}

} // namespace

ConfluenceCount countNetworkConfluences(const network::RiverNetwork& network) {
  ConfluenceCount count;
  for (const network::RiverNode& node : network.nodes) {
    if (node.children.size() < 2)
      continue;
    ++count.confluences;
    count.threeOrMore += node.children.size() >= 3 ? 1 : 0;
  }
  count.shareThreeOrMore =
      count.confluences == 0 ? kNaN : double(count.threeOrMore) / double(count.confluences);
  return count;
}

std::array<double, 4> meanSinuosity(const std::vector<primitives::RiverPrimitive>& rivers) {
  std::array<double, 4> sum{};
  std::array<std::size_t, 4> count{};
  for (const primitives::RiverPrimitive& river : rivers) {
    double length = 0.0;
    for (std::size_t k = 0; k + 1 < river.curve.size(); ++k)
      length += distance(river.curve[k].position, river.curve[k + 1].position);
    const double straight = river.curve.size() < 2 ? 0.0
                                                   : distance(river.curve.front().position,
                                                              river.curve.back().position);
    const std::size_t type = std::size_t(river.type);
    if (straight <= 0.0 || type >= sum.size())
      continue;
    sum[type] += length / straight;
    ++count[type];
  }
  std::array<double, 4> mean{};
  for (std::size_t t = 0; t < mean.size(); ++t)
    mean[t] = count[t] == 0 ? kNaN : sum[t] / double(count[t]);
  return mean;
}

NetworkReliefFigures compareWithRivers(const construction::World& world, const HeightRaster& raster,
                                       const FlowField& flow) {
  NetworkReliefFigures figures;
  const std::vector<float> toRivers = distanceToRivers(world, raster);
  figures.channelsNearRivers = channelsNearRivers(toRivers, flow);
  measureCoverage(toRivers, raster, figures);
  figures.riversNearChannels = riversNearChannels(world, raster, flow);
  figures.networkConfluences = countNetworkConfluences(world.data().network);
  const std::array<double, 4> sinuosity = meanSinuosity(world.data().rivers);
  figures.sinuosityB = sinuosity[std::size_t(primitives::RiverType::kStraight)];
  figures.sinuosityE = sinuosity[std::size_t(primitives::RiverType::kSinuous)];
  figures.sinuosityD = sinuosity[std::size_t(primitives::RiverType::kBraided)];
  figures.sinuosityDelta = sinuosity[std::size_t(primitives::RiverType::kDelta)];
  return figures;
}

} // namespace strahler::quality
