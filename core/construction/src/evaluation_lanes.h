#pragma once

#include "strahler/base/lanes.h"
#include "strahler/construction/world.h"

#include <array>
#include <cstdint>
#include <span>

namespace strahler::construction::detail {

/// The noise octaves alive at one sample spacing: the first `active` octaves, each scaled by
/// its LOD fade.
struct OctaveFades {
  double spacing = 0.0;
  int active = 0;
  std::array<double, NoiseOctaves::kOctaves> fade{};
};

/// The weighted sums of the terrain blend, base::kLanes each.
struct TerrainSums {
  alignas(64) double weight[base::kLanes];
  alignas(64) double height[base::kLanes];
  alignas(64) double amplitude[base::kLanes];
  alignas(64) double roughness[base::kLanes];
  alignas(64) double count[base::kLanes];
};

/// One call of the terrain blend: base::kLanes points (xs, ys) and their shared candidates;
/// results go to h and w (kLanes each).
struct TerrainLaneArgs {
  const World::HotTerrain* hot = nullptr;
  std::span<const std::uint32_t> ids;
  const OctaveFades* fades = nullptr;
  const noise::LatticeNoise* noise = nullptr;
  const double* xs = nullptr;
  const double* ys = nullptr;
  double* h = nullptr;
  double* w = nullptr;
  TerrainSums* sums = nullptr; ///< scratch for the sums
};

/// The terrain blend compiled for the instruction set in use (same bits on each).
void terrainLanes(const TerrainLaneArgs& args) noexcept;
/// The terrain blend at one point (xs[0], ys[0]) in scalar registers, into h[0] and w[0]:
/// the same bits as a lane of terrainLanes().
void terrainPoint(const TerrainLaneArgs& args) noexcept;

/// Segments of a river curve per chunk box (World keeps one box per run of kChunk segments).
inline constexpr std::size_t kChunk = 8;

/// One closest-point search on a river curve for base::kLanes points (xs, ys); points outside
/// the support box are not searched, nor runs of the curve before firstChunk or after the
/// chunks given. Results per lane: the distance to the curve (infinity when not searched or
/// not nearer than the radius) and, where finite, the segment of the closest point and the
/// fraction of the way along it.
struct CurveLaneArgs {
  double radius = 0.0;
  double reach = 0.0;     ///< World::riverReach(): the radius with a margin above rounding
  geometry::Aabb support; ///< the river's support box
  /// The box of each run of kChunk segments, up to the last run searched.
  std::span<const geometry::Aabb> chunks;
  std::size_t firstChunk = 0;                  ///< the first run searched
  std::span<const World::HotSegment> segments; ///< every segment of the curve
  const double* xs = nullptr;
  const double* ys = nullptr;
  double* distance = nullptr;
  std::int64_t* segment = nullptr;
  double* along = nullptr;
};

/// The closest-point search compiled for the instruction set in use (same bits on each);
/// returns the points that came within the river's radius (bit l: point l).
unsigned closestOnCurveLanes(const CurveLaneArgs& args) noexcept;
/// The closest-point search for one point (lane 0 of the arguments) in scalar registers: the
/// same bits as a lane of closestOnCurveLanes().
unsigned closestOnCurvePoint(const CurveLaneArgs& args) noexcept;

/// One nearest-segment search for base::kLanes points (xs, ys) over the segments `ids` of
/// `segments`: best2[l] becomes the least of itself and each segment's squared distance, as
/// geometry::closestPointOnSegment and lengthSquared compute it.
struct SegmentLaneArgs {
  const geometry::BoundarySegment* segments = nullptr;
  std::span<const std::uint32_t> ids;
  const double* xs = nullptr;
  const double* ys = nullptr;
  double* best2 = nullptr;
};

/// The nearest-segment search compiled for the instruction set in use (same bits on each).
void nearestSegmentLanes(const SegmentLaneArgs& args) noexcept;

} // namespace strahler::construction::detail
