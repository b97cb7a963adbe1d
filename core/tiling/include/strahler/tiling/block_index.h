#pragma once

#include "strahler/base/strong_id.h"
#include "strahler/construction/world_data.h"
#include "strahler/geometry/aabb.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace strahler::tiling {

/// An R-tree (Boost.Geometry) over each block's influence box: the box holding the supports
/// of all its terrain and river primitives. A tile needs only the blocks whose box meets it.
class BlockIndex {
public:
  /// Indexes the blocks of `world`.
  explicit BlockIndex(const construction::WorldData& world);
  ~BlockIndex();
  BlockIndex(BlockIndex&&) noexcept;
  BlockIndex& operator=(BlockIndex&&) noexcept;

  /// Blocks whose influence box meets `box`, in ascending order.
  std::vector<base::BlockId> blocksMeeting(const geometry::Aabb& box) const;
  /// Influence box of one block (empty when the block has no primitive).
  const geometry::Aabb& influence(base::BlockId block) const { return influence_[block.index()]; }

private:
  struct Tree;
  std::vector<geometry::Aabb> influence_;
  std::unique_ptr<Tree> tree_;
};

} // namespace strahler::tiling
