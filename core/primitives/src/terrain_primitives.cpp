#include "strahler/primitives/terrain_primitives.h"

#include "strahler/base/random.h"
#include "strahler/base/smoothstep.h"
#include "strahler/geometry/distance.h"
#include "strahler/network/relief_law.h"
#include "strahler/primitives/quantization.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace strahler::primitives {
namespace {

using geometry::Vec2;

constexpr std::uint64_t kTerrainStream = 0x7465727261696eull;
constexpr double kMinSpacingFraction = 0.6;
constexpr double kAmplitudePerMetreOfRelief = 0.3;
/// Steepest plane a primitive gets (tan 40°).
constexpr double kMaxHillslope = 0.84;
/// Share of that gradient a primitive's plane keeps: whole planes cross below the rivers at the
/// heads of hollows and leave closed bowls (docs/architecture.md, sloping terrain primitives).
constexpr double kPlaneShare = 0.25;

/// The jittered candidate of grid cell (i, j) and its random priority.
struct Candidate {
  Vec2 position;
  std::uint64_t priority = 0;
};

Candidate candidateAt(std::uint64_t seed, std::int64_t i, std::int64_t j) {
  const std::uint64_t h =
      base::mixHash(base::mixHash(seed ^ kTerrainStream, static_cast<std::uint64_t>(i)),
                    static_cast<std::uint64_t>(j));
  base::Rng rng(h);
  const double u = rng.uniform(), v = rng.uniform();
  return {{(static_cast<double>(i) + u) * kTerrainSpacing,
           (static_cast<double>(j) + v) * kTerrainSpacing},
          rng.nextU64()};
}

/// True when no neighbour candidate of higher priority is too close.
bool survives(std::uint64_t seed, std::int64_t i, std::int64_t j, const Candidate& c) {
  const double minDistance = kMinSpacingFraction * kTerrainSpacing;
  for (std::int64_t dj = -1; dj <= 1; ++dj)
    for (std::int64_t di = -1; di <= 1; ++di) {
      if (di == 0 && dj == 0)
        continue;
      const Candidate o = candidateAt(seed, i + di, j + dj);
      if (o.priority > c.priority && distance(o.position, c.position) < minDistance)
        return false;
    }
  return true;
}

bool inRegion(const geometry::MultiPolygon& region, Vec2 p) {
  for (const geometry::Polygon& piece : region)
    if (geometry::contains(piece, p))
      return true;
  return false;
}

/// Nearest point of a set of river curves (or ridges): distance, elevation there and the point.
struct RiverHit {
  double distance = std::numeric_limits<double>::infinity();
  double elevation = 0.0;
  Vec2 point;
};

RiverHit nearestRiver(const std::vector<const RiverPrimitive*>& curves, Vec2 p) {
  RiverHit best;
  for (const RiverPrimitive* r : curves)
    for (std::size_t k = 0; k + 1 < r->curve.size(); ++k) {
      const CurvePoint& a = r->curve[k];
      const CurvePoint& b = r->curve[k + 1];
      const Vec2 q = geometry::closestPointOnSegment(p, a.position, b.position);
      const double d = distance(p, q);
      if (d >= best.distance)
        continue;
      const double span = distance(a.position, b.position);
      const double t = span > 0 ? distance(a.position, q) / span : 0.0;
      best = {d, a.elevation + (b.elevation - a.elevation) * t, q};
    }
  return best;
}

/// A ridge segment of a block's cell with the elevations of its ends.
struct Ridge {
  Vec2 a, b;
  double za = 0.0, zb = 0.0;
};

std::vector<Ridge> ridgesOf(const analysis::Hydrology& h, network::NodeId id) {
  const blocks::Block& block = h.blocks.blocks[id.index()];
  const network::RiverNode& node = h.network.node(id);
  auto riverLinked = [&](network::NodeId other) {
    if (other == node.parent)
      return true;
    return std::find(node.children.begin(), node.children.end(), other) != node.children.end();
  };
  auto cornerElevation = [&](std::size_t k) {
    const std::uint32_t v = block.cellVertices[k];
    return v == blocks::kNoVertex ? node.elevation : h.analysis.ridgeElevation[v];
  };
  std::vector<Ridge> ridges;
  const std::size_t n = block.cell.size();
  for (std::size_t k = 0; k < n; ++k) {
    const network::NodeId across = block.neighbours[k];
    if (!across.valid() || riverLinked(across))
      continue;
    ridges.push_back(
        {block.cell[k], block.cell[(k + 1) % n], cornerElevation(k), cornerElevation((k + 1) % n)});
  }
  return ridges;
}

/// Nearest ridge point: distance and elevation (linear along the ridge segment).
RiverHit nearestRidge(const std::vector<Ridge>& ridges, Vec2 p) {
  RiverHit best;
  for (const Ridge& r : ridges) {
    const Vec2 q = geometry::closestPointOnSegment(p, r.a, r.b);
    const double d = distance(p, q);
    if (d >= best.distance)
      continue;
    const double span = distance(r.a, r.b);
    best = {d, r.za + (r.zb - r.za) * (span > 0 ? distance(r.a, q) / span : 0.0), q};
  }
  return best;
}

class BlockTerrain {
public:
  BlockTerrain(const input::WorldSpec& spec, const analysis::Hydrology& h,
               const std::vector<const RiverPrimitive*>& riverOfNode)
      : spec_(spec), h_(h), riverOfNode_(riverOfNode), relief_(spec, *h.land) {}

  /// The primitives of block `id`, and in `bases` (when given) the river point each rises from.
  std::vector<TerrainPrimitive> build(network::NodeId id, std::vector<TerrainBase>* bases) const {
    const blocks::Block& block = h_.blocks.blocks[id.index()];
    std::vector<TerrainPrimitive> out;
    if (block.region.empty())
      return out;
    geometry::Aabb box;
    for (const geometry::Polygon& piece : block.region)
      box.add(geometry::bounds(piece.outer));
    const std::vector<const RiverPrimitive*> curves = riversAround(id);
    const std::vector<Ridge> ridges = ridgesOf(h_, id);
    const auto i0 = static_cast<std::int64_t>(std::floor(box.min.x / kTerrainSpacing));
    const auto i1 = static_cast<std::int64_t>(std::floor(box.max.x / kTerrainSpacing));
    const auto j0 = static_cast<std::int64_t>(std::floor(box.min.y / kTerrainSpacing));
    const auto j1 = static_cast<std::int64_t>(std::floor(box.max.y / kTerrainSpacing));
    const std::uint64_t seed = spec_.params.seed;
    for (std::int64_t j = j0; j <= j1; ++j)
      for (std::int64_t i = i0; i <= i1; ++i) {
        const Candidate c = candidateAt(seed, i, j);
        if (!box.contains(c.position) || !inRegion(block.region, c.position))
          continue;
        if (!survives(seed, i, j, c))
          continue;
        out.push_back(primitiveAt(c.position, id, curves, ridges, bases));
      }
    return out;
  }

private:
  /// The river sections of a block: the one below its node and those arriving at it.
  std::vector<const RiverPrimitive*> riversAround(network::NodeId id) const {
    std::vector<const RiverPrimitive*> curves;
    if (riverOfNode_[id.index()])
      curves.push_back(riverOfNode_[id.index()]);
    for (network::NodeId c : h_.network.node(id).children)
      curves.push_back(riverOfNode_[c.index()]);
    return curves;
  }

  TerrainPrimitive primitiveAt(Vec2 c, network::NodeId id,
                               const std::vector<const RiverPrimitive*>& curves,
                               const std::vector<Ridge>& ridges,
                               std::vector<TerrainBase>* bases) const {
    const network::RiverNode& node = h_.network.node(id);
    RiverHit a = nearestRiver(curves, c);
    if (!std::isfinite(a.distance))
      a = {distance(c, node.position), node.elevation, node.position};
    RiverHit b = nearestRidge(ridges, c);
    // Unit vectors from the river point and the ridge point to c (no ridge: straight on).
    const Vec2 fromRiver = a.distance > 0 ? (c - a.point) * (1.0 / a.distance) : Vec2{};
    if (!std::isfinite(b.distance))
      b = {kTerrainSpacing, a.elevation + relief_.ridgeLambda(c) * kTerrainSpacing,
           c + fromRiver * kTerrainSpacing};
    const Vec2 fromRidge = b.distance > 0 ? (c - b.point) * (1.0 / b.distance) : Vec2{};
    const double sum = a.distance + b.distance;
    const double cz =
        sum > 0 ? (a.distance * b.elevation + b.distance * a.elevation) / sum : a.elevation;
    // ∇cz with the river's and ridge's elevations held: (z_b − z_a)(u_a d_b − u_b d_a) / (d_a
    // + d_b)², u the unit vectors above; at most kMaxHillslope.
    Vec2 slope = sum > 0 ? (fromRiver * b.distance - fromRidge * a.distance) *
                               ((b.elevation - a.elevation) / (sum * sum))
                         : Vec2{};
    if (const double steepness = length(slope); steepness > kMaxHillslope)
      slope = slope * (kMaxHillslope / steepness);
    const double relief = std::max(0.0, b.elevation - a.elevation);
    const double amplitude = kAmplitudePerMetreOfRelief * relief *
                             base::smoothstep(a.distance / (0.6 * kTerrainSpacing));
    if (bases)
      bases->push_back({a.elevation, a.distance});
    TerrainPrimitive t;
    t.center = quantize(c);
    t.radius = quantize(kTerrainRadiusInSpacings * kTerrainSpacing, Quantum::kRadius);
    t.elevation = quantize(cz, Quantum::kElevation);
    slope = slope * kPlaneShare;
    t.slope = {quantize(slope.x, Quantum::kSlope), quantize(slope.y, Quantum::kSlope)};
    t.amplitude = quantize(amplitude, Quantum::kElevation);
    t.roughness = quantize(0.4 + 0.1 * relief_.mountainousness(c), Quantum::kRoughness);
    return t;
  }

  const input::WorldSpec& spec_;
  const analysis::Hydrology& h_;
  const std::vector<const RiverPrimitive*>& riverOfNode_;
  network::ReliefLaw relief_;
};

} // namespace

std::vector<std::vector<TerrainPrimitive>>
generateTerrainPrimitives(const input::WorldSpec& spec, const analysis::Hydrology& hydrology,
                          const std::vector<RiverPrimitive>& rivers,
                          std::vector<std::vector<TerrainBase>>* bases) {
  std::vector<const RiverPrimitive*> riverOfNode(hydrology.network.nodes.size(), nullptr);
  for (const RiverPrimitive& r : rivers)
    riverOfNode[r.node.index()] = &r;
  const BlockTerrain terrain(spec, hydrology, riverOfNode);
  std::vector<std::vector<TerrainPrimitive>> out(hydrology.network.nodes.size());
  if (bases)
    bases->assign(out.size(), {});
  for (std::uint32_t i = 0; i < out.size(); ++i)
    out[i] = terrain.build(network::NodeId(i), bases ? &(*bases)[i] : nullptr);
  return out;
}

} // namespace strahler::primitives
