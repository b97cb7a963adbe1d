#include "strahler/blocks/block_set.h"

#include "land_clipper.h"
#include "voronoi.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>

namespace strahler::blocks {
namespace {

using geometry::Aabb;
using geometry::Vec2;

/// Frame margin: this fraction of the diagonal of the land and nodes, plus kFrameMarginMin.
constexpr double kFrameMarginFraction = 0.1;
constexpr double kFrameMarginMin = 1000.0; // metres

std::string describe(Vec2 p) {
  std::ostringstream out;
  out.precision(17);
  out << '(' << p.x << ", " << p.y << ')';
  return out.str();
}

/// Fails unless every site is finite and no two coincide (the Voronoi cell of a repeated
/// node would be empty).
base::Status checkSites(const std::vector<Vec2>& sites) {
  for (std::size_t i = 0; i < sites.size(); ++i)
    if (!std::isfinite(sites[i].x) || !std::isfinite(sites[i].y))
      return base::makeError(base::ErrorCode::kInvalidInput, "river node " + std::to_string(i) +
                                                                 " has a non-finite position " +
                                                                 describe(sites[i]));
  std::vector<std::uint32_t> order(sites.size());
  std::iota(order.begin(), order.end(), 0u);
  auto key = [&](std::uint32_t i) { return std::tuple(sites[i].x, sites[i].y, i); };
  std::sort(order.begin(), order.end(),
            [&](std::uint32_t a, std::uint32_t b) { return key(a) < key(b); });
  for (std::size_t k = 1; k < order.size(); ++k)
    if (sites[order[k]] == sites[order[k - 1]])
      return base::makeError(base::ErrorCode::kInvalidInput,
                             "river nodes " + std::to_string(order[k - 1]) + " and " +
                                 std::to_string(order[k]) + " are at the same position " +
                                 describe(sites[order[k]]));
  return base::Ok{};
}

/// The box every cell is clipped to: land and nodes, plus a margin.
Aabb frameFor(const std::vector<Vec2>& sites, const geometry::PolygonIndex& land) {
  Aabb box = land.bounds();
  for (Vec2 p : sites)
    box.add(p);
  if (box.empty())
    box.add(Vec2{});
  return box.expanded(kFrameMarginFraction * geometry::length(box.size()) + kFrameMarginMin);
}

} // namespace

base::Result<BlockSet> buildBlocks(const network::RiverNetwork& network,
                                   const geometry::PolygonIndex& land) {
  std::vector<Vec2> sites;
  sites.reserve(network.nodes.size());
  for (const network::RiverNode& node : network.nodes)
    sites.push_back(node.position);
  STRAHLER_RETURN_IF_ERROR(checkSites(sites));

  BlockSet set;
  set.frame = frameFor(sites, land);
  detail::VoronoiDiagram diagram = detail::buildVoronoi(sites, set.frame);
  const detail::LandClipper clipper(land.polygons());
  set.blocks.resize(sites.size());
  for (std::size_t i = 0; i < sites.size(); ++i) {
    Block& block = set.blocks[i];
    detail::TaggedRing& cell = diagram.cells[i];
    block.node = NodeId(static_cast<std::uint32_t>(i));
    block.cell = std::move(cell.points);
    block.cellVertices = std::move(cell.vertices);
    block.neighbours = std::move(cell.neighbours);
    block.region = clipper.clip(block.cell);
    block.area = geometry::area(block.region);
  }
  set.vertices = std::move(diagram.vertices);
  return set;
}

} // namespace strahler::blocks
