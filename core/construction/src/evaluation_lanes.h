#pragma once

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
};

/// The terrain blend compiled for the instruction set in use (same bits on each).
void terrainLanes(const TerrainLaneArgs& args) noexcept;
/// The terrain blend at one point (xs[0], ys[0]) in scalar registers, into h[0] and w[0]:
/// the same bits as a lane of terrainLanes().
void terrainPoint(const TerrainLaneArgs& args) noexcept;

/// Segments of a river curve per chunk box (World keeps one box per run of kChunk segments).
inline constexpr std::size_t kChunk = 8;

/// One closest-point search on a river curve for base::kLanes points (xs, ys); lanes with
/// active[l] == 0 are not searched. Results per lane: the distance to the curve (infinity when
/// not searched or farther than the river's radius), the water elevation there and the
/// fraction along the curve (0 upstream .. 1 downstream).
struct CurveLaneArgs {
  const primitives::RiverPrimitive* river = nullptr;
  std::span<const geometry::Aabb> chunks; ///< the box of each run of kChunk segments
  const double* xs = nullptr;
  const double* ys = nullptr;
  const std::int64_t* active = nullptr;
  double* distance = nullptr;
  double* elevation = nullptr;
  double* along = nullptr;
};

/// The closest-point search compiled for the instruction set in use (same bits on each).
void closestOnCurveLanes(const CurveLaneArgs& args) noexcept;
/// The closest-point search for one point (lane 0 of the arguments) in scalar registers: the
/// same bits as a lane of closestOnCurveLanes().
void closestOnCurvePoint(const CurveLaneArgs& args) noexcept;

} // namespace strahler::construction::detail
