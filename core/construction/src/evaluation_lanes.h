#pragma once

#include "strahler/construction/world.h"
#include "strahler/primitives/river_primitives.h"
#include "strahler/simd/lanes.h"

#include <array>
#include <cstdint>
#include <span>

namespace strahler::construction::detail {

class Folds;

/// The noise octaves alive at one sample spacing: the first `active` octaves, each scaled by
/// its LOD fade.
struct OctaveFades {
  double spacing = 0.0;
  int active = 0;
  std::array<double, NoiseOctaves::kOctaves> fade{};
};

/// Points of one call of the terrain blend at most: two groups of simd::kLanes (two runs of
/// samples that share their candidates).
inline constexpr std::size_t kTerrainLanes = 2 * simd::kLanes;

/// The weighted sums of the terrain blend, kTerrainLanes each.
struct TerrainSums {
  alignas(64) double weight[kTerrainLanes];
  alignas(64) double height[kTerrainLanes];
  alignas(64) double amplitude[kTerrainLanes];
  alignas(64) double roughness[kTerrainLanes];
  alignas(64) double count[kTerrainLanes];
  alignas(64) double slopeX[kTerrainLanes];       ///< Σ g_i dx_i (∇w_i = −4 g_i d_i)
  alignas(64) double slopeY[kTerrainLanes];       ///< Σ g_i dy_i
  alignas(64) double slopeHeightX[kTerrainLanes]; ///< Σ g_i dx_i h_i (h_i: i's plane at the point)
  alignas(64) double slopeHeightY[kTerrainLanes]; ///< Σ g_i dy_i h_i
  alignas(64) double planeX[kTerrainLanes];       ///< Σ w_i s_i.x (the planes' gradients)
  alignas(64) double planeY[kTerrainLanes];       ///< Σ w_i s_i.y
};

/// One call of the terrain blend: `groups` groups (1 or 2) of simd::kLanes points, group g at
/// points[g], with their shared candidates; results go to h and w, groups · kLanes each,
/// group after group.
struct TerrainLaneArgs {
  const World::HotTerrain* hot = nullptr;
  std::span<const std::uint32_t> ids;
  std::array<const OctaveFades*, 2> fades{}; ///< of each group's spacing
  const noise::LatticeNoise* noise = nullptr;
  std::uint32_t gullySeed = 0; ///< shuffles the gully octaves' phases
  /// Whether octaves 2–6 are gully octaves (false on eroded worlds: gradient noise, as the
  /// erosion's residual carries the drainage below the graph's scale).
  bool gullies = true;
  std::array<const geometry::Vec2*, 2> points{};
  std::size_t groups = 1;
  double* h = nullptr;
  double* w = nullptr;
  TerrainSums* sums = nullptr; ///< scratch for the sums
  /// The tectonic folds added to the blend (Folds::at), or null: none (no drawn mountains).
  const Folds* folds = nullptr;
};

/// The terrain blend compiled for the instruction set in use (same bits on each).
void terrainLanes(const TerrainLaneArgs& args) noexcept;
/// The terrain blend at one point (points[0][0]) in scalar registers, into h[0] and w[0]:
/// the same bits as a lane of terrainLanes().
void terrainPoint(const TerrainLaneArgs& args) noexcept;

/// Segments of a river curve per chunk box (World keeps one box per run of kChunk segments).
inline constexpr std::size_t kChunk = 8;

/// The rivers' union U(R…) at simd::kLanes points (riversLanes) or one (riversPoint): for each
/// candidate in turn, the closest point of its curve to each point (points outside its support
/// box are not searched, nor runs of the curve before firstChunk or from endChunk on; ties keep
/// the first segment) and, within its radius, its profile's sample (primitives::riverProfile,
/// weight primitives::riverWeight), united with the samples before it by the deeper cut into
/// the terrain (operators.h: uniteByCut). Points no river reaches get {0, 0}.
struct RiverLaneArgs {
  std::span<const World::RiverCandidate> rivers;
  const World::HotRiver* hot = nullptr;        ///< per river primitive
  const geometry::Aabb* chunks = nullptr;      ///< every river's runs' boxes
  const World::HotSegment* segments = nullptr; ///< every river's segments
  /// Per segment, its water elevation at its start, then its rise to its end.
  const double* water = nullptr;
  const geometry::Vec2* points = nullptr;
  double spacing = 0.0; ///< between the samples, m: sets the channels' floors (riverFloor)
  const double* terrain = nullptr; ///< the terrain blend's height at each point
  double* riverH = nullptr;
  double* riverW = nullptr;
};

/// The rivers' union compiled for the instruction set in use (same bits on each).
void riversLanes(const RiverLaneArgs& args) noexcept;
/// The rivers' union at one point (points[0]) in scalar registers: the same bits as a lane of
/// riversLanes().
void riversPoint(const RiverLaneArgs& args) noexcept;

/// The coast shaping at simd::kLanes points (World's CoastShape): from the terrain blend
/// (h, w), the rivers' union (riverH, riverW), whether each point is on land (onLand: 1 or 0)
/// and its squared distance to the shore (shore2, capped by the caller at the reach of its
/// side or beyond), the final heights.
struct CoastLaneArgs {
  const double* h = nullptr;
  const double* w = nullptr;
  const double* riverH = nullptr;
  const double* riverW = nullptr;
  const double* onLand = nullptr;
  const double* shore2 = nullptr;
  double* heights = nullptr;
};

/// The coast shaping compiled for the instruction set in use (same bits on each).
void coastLanes(const CoastLaneArgs& args) noexcept;
/// The coast shaping of one point in scalar registers, `shore` metres from the boundary (at
/// most CoastShape::kBand on land, World::shelfReach() at sea): the same bits as a lane of
/// coastLanes() whose shore2 gives that distance.
double coastPoint(Sample terrain, Sample rivers, bool onLand, double shore) noexcept;
/// coastPoint() at sea beyond the shelf's reach, its depth computed once: the same bits.
double farSeaPoint(Sample rivers) noexcept;

/// One nearest-segment search for simd::kLanes points over the segments `ids` of
/// `segments`: best2[l] becomes the least of itself and each segment's squared distance, as
/// geometry::closestPointOnSegment and lengthSquared compute it.
struct SegmentLaneArgs {
  const geometry::BoundarySegment* segments = nullptr;
  std::span<const std::uint32_t> ids;
  const geometry::Vec2* points = nullptr;
  double* best2 = nullptr;
};

/// The nearest-segment search compiled for the instruction set in use (same bits on each).
void nearestSegmentLanes(const SegmentLaneArgs& args) noexcept;

/// Point in land for simd::kLanes points that share one ray band of the land's index
/// (geometry::PolygonIndex::rayBand): onLand[l] becomes 1 where point l lies within `bounds`
/// and an odd number of the band's segments `ids` cross its ray, else 0; the decisions of
/// PolygonIndex::contains, made by the same operations.
struct InsideLaneArgs {
  const geometry::BoundarySegment* segments = nullptr;
  std::span<const std::uint32_t> ids;
  geometry::Aabb bounds;
  const geometry::Vec2* points = nullptr;
  double* onLand = nullptr;
};

/// The point-in-land test compiled for the instruction set in use.
void insideLanes(const InsideLaneArgs& args) noexcept;

} // namespace strahler::construction::detail
