#pragma once

#include "strahler/analysis/hydrology.h"
#include "strahler/input/world_spec.h"
#include "strahler/primitives/river_primitive.h"
#include "strahler/primitives/terrain_primitive.h"

#include <vector>

namespace strahler::primitives {

/// The river point a terrain primitive rises from (the nearest point of its block's rivers).
struct TerrainBase {
  double elevation = 0.0; ///< Its elevation, m.
  double distance = 0.0;  ///< Its distance from the primitive's centre, m.
};

/// Spacing of the terrain-primitive grid, m: about 10 primitives per km², as in the paper.
inline constexpr double kTerrainSpacing = 260.0;
/// Radius of every terrain primitive, in spacings: wide enough that the discs cover the land.
inline constexpr double kTerrainRadiusInSpacings = 2.2;

/// Terrain primitives of every block (Section 7.2), blocks in node order.
/// Centres: one jittered candidate per cell of a global grid of side kTerrainSpacing, dropped
/// when a neighbour candidate of higher random priority lies closer than 0.6 spacings (a
/// Poisson-disk set that any block can generate alone); a block keeps the centres inside its
/// region. c_z interpolates between the nearest point a of the block's rivers and the
/// nearest point b of its ridges: c_z = (d_a b_z + d_b a_z) / (d_a + d_b). The noise
/// amplitude grows with the ridge–river height difference and fades out near the river; the
/// roughness grows with the mountainousness. `rivers` holds one primitive per non-mouth node,
/// in node order (generateRiverPrimitives). With `bases`, bases[i][k] is the river point
/// primitive k of block i rises from (what the drawn features' relief acts on, drawn_relief.h).
std::vector<std::vector<TerrainPrimitive>>
generateTerrainPrimitives(const input::WorldSpec& spec, const analysis::Hydrology& hydrology,
                          const std::vector<RiverPrimitive>& rivers,
                          std::vector<std::vector<TerrainBase>>* bases = nullptr);

} // namespace strahler::primitives
