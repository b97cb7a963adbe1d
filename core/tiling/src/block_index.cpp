#include "strahler/tiling/block_index.h"

#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <boost/iterator/function_output_iterator.hpp>

#include <algorithm>

namespace strahler::tiling {
namespace {

namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;
using Point = bg::model::point<double, 2, bg::cs::cartesian>;
using Box = bg::model::box<Point>;
using Entry = std::pair<Box, std::uint32_t>;

/// Up to this many blocks found are sorted; more are collected in order by marking.
constexpr std::size_t kSortedBelow = 256;

Box toBox(const geometry::Aabb& a) {
  return {{a.min.x, a.min.y}, {a.max.x, a.max.y}};
}

} // namespace

struct BlockIndex::Tree {
  bgi::rtree<Entry, bgi::rstar<16>> rtree;
};

BlockIndex::BlockIndex(const construction::WorldData& world) : tree_(std::make_unique<Tree>()) {
  influence_.resize(world.blocks.size());
  std::vector<Entry> entries;
  for (std::uint32_t b = 0; b < world.blocks.size(); ++b) {
    const construction::BlockPrimitives& range = world.blocks[b];
    geometry::Aabb box;
    for (std::uint32_t i = range.terrainBegin; i < range.terrainEnd; ++i) {
      const primitives::TerrainPrimitive& t = world.terrain[i];
      box.add(geometry::Aabb{t.center, t.center}.expanded(t.radius));
    }
    for (std::uint32_t i = range.riverBegin; i < range.riverEnd; ++i)
      box.add(primitives::supportBox(world.rivers[i]));
    influence_[b] = box;
    if (!box.empty())
      entries.emplace_back(toBox(box), b);
  }
  tree_->rtree = bgi::rtree<Entry, bgi::rstar<16>>(entries.begin(), entries.end()); // packed
}

BlockIndex::~BlockIndex() = default;
BlockIndex::BlockIndex(BlockIndex&&) noexcept = default;
BlockIndex& BlockIndex::operator=(BlockIndex&&) noexcept = default;

std::vector<base::BlockId> BlockIndex::blocksMeeting(const geometry::Aabb& box) const {
  std::vector<base::BlockId> out;
  if (box.empty())
    return out;
  tree_->rtree.query(bgi::intersects(toBox(box)),
                     boost::iterators::make_function_output_iterator(
                         [&](const Entry& e) { out.push_back(base::BlockId(e.second)); }));
  if (out.size() <= kSortedBelow) {
    std::sort(out.begin(), out.end());
    return out;
  }
  // Many blocks: marked and collected in one pass (sorting thousands of ids in the tree's
  // order costs a mispredicted branch per comparison).
  std::vector<char> found(influence_.size(), 0);
  for (const base::BlockId b : out)
    found[b.index()] = 1;
  out.resize(found.size());
  std::size_t n = 0;
  for (std::uint32_t b = 0; b < found.size(); ++b) { // without a branch per block
    out[n] = base::BlockId(b);
    n += static_cast<std::size_t>(found[b]);
  }
  out.resize(n);
  return out;
}

} // namespace strahler::tiling
