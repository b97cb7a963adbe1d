#pragma once

#include "strahler/base/random.h"
#include "strahler/blocks/block_set.h"
#include "strahler/geometry/polygon.h"
#include "strahler/geometry/polygon_index.h"
#include "strahler/network/river_network.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace strahler::blocks::test_support {

using geometry::Ring;
using geometry::Vec2;

/// A network whose nodes sit at `positions` (the tree shape does not matter to blocks).
inline network::RiverNetwork networkAt(const std::vector<Vec2>& positions) {
  network::RiverNetwork network;
  for (Vec2 p : positions) {
    network::RiverNode node;
    node.position = p;
    network.nodes.push_back(node);
  }
  return network;
}

/// Counter-clockwise rectangle.
inline Ring rectangle(Vec2 min, Vec2 max) {
  return {min, {max.x, min.y}, max, {min.x, max.y}};
}

/// `count` random points inside the land.
inline std::vector<Vec2> randomPointsIn(const geometry::PolygonIndex& land, std::size_t count,
                                        base::Rng& rng) {
  const geometry::Aabb box = land.bounds();
  std::vector<Vec2> points;
  while (points.size() < count) {
    const Vec2 p{rng.uniform(box.min.x, box.max.x), rng.uniform(box.min.y, box.max.y)};
    if (land.contains(p))
      points.push_back(p);
  }
  return points;
}

/// Builds the blocks and fails the test on error.
inline BlockSet build(const std::vector<Vec2>& sites, const geometry::PolygonIndex& land) {
  auto result = buildBlocks(networkAt(sites), land);
  EXPECT_TRUE(result.ok()) << (result.ok() ? "" : result.error().message);
  return result.ok() ? std::move(result).value() : BlockSet{};
}

/// Sum of the block areas.
inline double totalArea(const BlockSet& set) {
  double total = 0.0;
  for (const Block& block : set.blocks)
    total += block.area;
  return total;
}

/// Area of cell ∩ land computed the slow, obvious way: every ring clipped whole.
inline double naiveClippedArea(const Ring& cell, const geometry::MultiPolygon& land) {
  double total = 0.0;
  for (const geometry::Polygon& polygon : land) {
    double a = std::abs(geometry::signedArea(geometry::clipToConvex(polygon.outer, cell)));
    for (const Ring& hole : polygon.holes)
      a -= std::abs(geometry::signedArea(geometry::clipToConvex(hole, cell)));
    total += a;
  }
  return total;
}

/// Distance from p to the nearest edge line of a convex ring; negative outside.
inline double insideDepth(const Ring& convex, Vec2 p) {
  double depth = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < convex.size(); ++i) {
    const Vec2 a = convex[i], b = convex[(i + 1) % convex.size()];
    depth = std::min(depth, geometry::cross(b - a, p - a) / geometry::distance(a, b));
  }
  return depth;
}

/// Structural invariants of every block: aligned tags, a convex counter-clockwise cell that
/// holds its node, corners that match their Voronoi vertex, symmetric neighbours whose
/// bisector carries the shared edge, and a region inside the cell.
inline void expectConsistentBlocks(const BlockSet& set, const std::vector<Vec2>& sites) {
  ASSERT_EQ(set.blocks.size(), sites.size());
  const double scale = geometry::length(set.frame.size());
  for (std::size_t i = 0; i < set.blocks.size(); ++i) {
    const Block& b = set.blocks[i];
    ASSERT_EQ(b.node.index(), i);
    ASSERT_GE(b.cell.size(), 3u);
    ASSERT_EQ(b.cellVertices.size(), b.cell.size());
    ASSERT_EQ(b.neighbours.size(), b.cell.size());
    EXPECT_GT(geometry::signedArea(b.cell), 0.0) << "block " << i;
    EXPECT_GT(insideDepth(b.cell, sites[i]), 0.0) << "block " << i;
    const std::size_t n = b.cell.size();
    for (std::size_t k = 0; k < n; ++k) {
      const Vec2 p = b.cell[k], q = b.cell[(k + 1) % n], r = b.cell[(k + 2) % n];
      EXPECT_GE(geometry::cross(q - p, r - q), -1e-9 * scale * scale) << "block " << i;
      if (b.cellVertices[k] != kNoVertex) {
        const VoronoiVertex& v = set.vertices.at(b.cellVertices[k]);
        EXPECT_EQ(v.position, p);
        EXPECT_TRUE(std::count(v.sites.begin(), v.sites.end(), b.node) == 1) << "block " << i;
      }
      const NodeId w = b.neighbours[k];
      if (!w.valid())
        continue;
      const auto& back = set.blocks.at(w.index()).neighbours;
      EXPECT_TRUE(std::count(back.begin(), back.end(), b.node) == 1) << i << " / " << w.value;
      for (Vec2 end : {p, q})
        EXPECT_NEAR(geometry::distance(end, sites[i]), geometry::distance(end, sites[w.index()]),
                    1e-7 * scale);
    }
    for (const geometry::Polygon& piece : b.region)
      for (Vec2 p : piece.outer)
        EXPECT_GE(insideDepth(b.cell, p), -1e-7 * scale);
  }
}

/// Every sampled land point lies in the region of its nearest node (points within 1e-6 m of
/// a cell border or the coast are skipped: either side is right there).
inline void expectNearestNodeOwnsPoints(const BlockSet& set, const std::vector<Vec2>& sites,
                                        const geometry::PolygonIndex& land, std::size_t samples,
                                        base::Rng& rng) {
  std::size_t checked = 0;
  for (const Vec2 p : randomPointsIn(land, samples, rng)) {
    std::size_t best = 0, second = 0;
    double d1 = std::numeric_limits<double>::infinity(), d2 = d1;
    for (std::size_t i = 0; i < sites.size(); ++i) {
      const double d = geometry::distance(p, sites[i]);
      if (d < d1) {
        second = best, d2 = d1, best = i, d1 = d;
      } else if (d < d2) {
        second = i, d2 = d;
      }
    }
    if (sites.size() > 1) {
      const double toBisector = (d2 * d2 - d1 * d1) / (2.0 * distance(sites[best], sites[second]));
      if (toBisector < 1e-6)
        continue;
    }
    if (land.distanceToBoundary(p, 1e-6) < 1e-6)
      continue;
    const auto& region = set.blocks[best].region;
    const bool inside = std::any_of(region.begin(), region.end(), [&](const auto& piece) {
      return geometry::contains(piece, p);
    });
    EXPECT_TRUE(inside) << "point (" << p.x << ", " << p.y << ") not in block " << best;
    ++checked;
  }
  EXPECT_GT(checked, samples * 9 / 10);
}

} // namespace strahler::blocks::test_support
