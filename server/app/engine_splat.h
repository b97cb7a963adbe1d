#pragma once
// `strahler export-heightmap --splat`: the layer weights a game engine blends its terrain
// materials with, from the slope, sediment, vegetation and water of the exported grid.

#include "engine_heightmap.h"

#include "strahler/base/result.h"
#include "strahler/construction/world.h"
#include "strahler/geometry/aabb.h"

#include <array>
#include <atomic>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace strahler::app {

/// The splat layers, in the order of the files and of the alphamaps' channels.
inline constexpr int kSplatLayerCount = 5;
/// The layers' names (Unreal target layer names, file suffixes, sidecar): bare ground, rock
/// (steep slopes), sediment, vegetation, water.
inline constexpr std::array<const char*, kSplatLayerCount> kSplatLayerNames{
    "Ground", "Rock", "Sediment", "Vegetation", "Water"};
/// Slopes (degrees) where rock starts to show and where it covers everything.
inline constexpr double kRockFromDeg = 30.0, kRockFullDeg = 50.0;
/// Sediment thickness (m) at which the sediment layer reaches full weight.
inline constexpr double kSedimentFullM = 1.0;

/// One layer score per splat layer, ≥ 0.
using SplatScores = std::array<float, kSplatLayerCount>;

/// The scores of one sample: water 1 (alone) on water; else rock r = smoothstep of the slope
/// from kRockFromDeg to kRockFullDeg, sediment min(1, S / kSedimentFullM)·(1 − r), vegetation
/// min(1, density)·(1 − r), ground 1 − r − max(sediment, vegetation). Never all 0.
SplatScores splatScores(double slopeDeg, double sedimentM, double vegetation, bool water) noexcept;

/// 255 split among the layers in proportion to `scores` (not all 0): each its floor, then the
/// remainder one each to the largest fractional parts (ties to the earlier layer). The bytes
/// sum to exactly 255.
std::array<std::uint8_t, kSplatLayerCount> splatWeights(const SplatScores& scores) noexcept;

/// The grid the splat maps are made of: the exported samples.
struct SplatGrid {
  geometry::Aabb box;              ///< Local metres; sample (0, 0) at (min.x, max.y).
  int size = 0;                    ///< Samples per side.
  std::span<const float> heights;  ///< size², row 0 north, m (eroded with --erode).
  std::span<const float> sediment; ///< size² from the erosion, m; empty: the local proxy.
};

/// One splat file: its name's suffix (after the heightmap's stem) and bytes.
struct SplatFile {
  std::string suffix; ///< e.g. "_splat_Rock.png" or "_alphamap0.png".
  std::string bytes;  ///< The PNG.
};

/// kInvalidInput when `engine`'s splat files cannot be written for a size × size export cut in
/// tilesX × tilesY tiles (Unity alphamaps: (size − 1)² ≤ 4096²; the others' weight PNGs: a
/// tile's side ≤ 4096).
base::Status checkSplat(Engine engine, int size, int tilesX, int tilesY);

/// The splat files of `engine`, row 0 north: Unity two RGBA alphamaps of (size − 1)² texels
/// (Ground, Rock, Sediment, Vegetation; Water, 0, 0, 0), each texel the mean of its four
/// corner samples' scores; the others one 8-bit grey PNG per layer at size × size, or with
/// tilesX × tilesY > 1 (Unreal's --tiles) one per layer and tile, cut as the heightmap's tiles
/// (suffix _splat_LAYER_x{A}_y{B}.png). Every pixel's weights sum to 255. Same bytes for any
/// `threads`; `rowsDone` counts sample rows.
base::Result<std::vector<SplatFile>> renderSplat(const construction::World& world, Engine engine,
                                                 const SplatGrid& grid, int threads,
                                                 std::atomic<long long>& rowsDone, int tilesX = 1,
                                                 int tilesY = 1);

} // namespace strahler::app
