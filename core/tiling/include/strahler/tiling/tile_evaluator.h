#pragma once

#include "strahler/construction/world.h"
#include "strahler/tiling/block_index.h"
#include "strahler/tiling/candidate_filters.h"
#include "strahler/tiling/tile_scheme.h"

#include <vector>

namespace strahler::tiling {

/// What one tile's evaluation touched.
struct TileStats {
  std::size_t blocks = 0;            ///< Blocks whose influence box meets the tile.
  std::size_t terrainPrimitives = 0; ///< Terrain primitives gathered from them.
  std::size_t riverPrimitives = 0;   ///< River primitives gathered from them.
};

/// Evaluates tiles from only the primitives of the blocks that influence them: the block
/// index finds the blocks, their primitives are binned over the tile, and every sample is
/// evaluated from its bin (construction::World::evaluateFrom), so a tile's heights are
/// bit-identical to the whole-world evaluator's at the same points and spacing. Thread-safe.
class TileEvaluator {
public:
  /// An evaluator over `world`, which must outlive it.
  explicit TileEvaluator(const construction::World& world);

  /// Heights (m) at every sample of `grid`, row-major like grid.points.
  std::vector<double> evaluate(const SampleGrid& grid, TileStats* stats = nullptr) const;

  /// The world evaluated.
  const construction::World& world() const noexcept { return world_; }
  /// The block index.
  const BlockIndex& blocks() const noexcept { return blocks_; }

private:
  const construction::World& world_;
  BlockIndex blocks_;
  TerrainDiscs terrainDiscs_; // per terrain primitive
};

} // namespace strahler::tiling
