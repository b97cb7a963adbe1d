// WorldData -> strahler.v1.World. Everything the reader derives or checks is asserted here,
// so that a world this encoder accepts always reads back equal.

#include "feature_codec.h"
#include "relief_codec.h"
#include "world_proto.h"

#include "strahler/input/params.h"
#include "strahler/primitives/quantization.h"
#include "strahler/store/world_file.h"

#include <cmath>
#include <limits>

namespace strahler::store::detail {
namespace {

using construction::WorldData;
using primitives::Quantum;
using Int64Column = google::protobuf::RepeatedField<std::int64_t>;

constexpr std::uint32_t kNoMouth = std::numeric_limits<std::uint32_t>::max();

/// k such that value == k · step exactly.
std::int64_t quanta(double value, double step) {
  STRAHLER_ASSERT(std::isfinite(value), "a world value is not finite");
  const double q = value / step;
  STRAHLER_ASSERT(std::abs(q) < 0x1p62, "a world value is too large for the world file");
  const auto k = static_cast<std::int64_t>(std::llround(q));
  STRAHLER_ASSERT(k >= -kMaxQuanta && k <= kMaxQuanta,
                  "a world value is too large for the world file");
  STRAHLER_ASSERT(static_cast<double>(k) * step == value,
                  "a world value is not on its quantum grid (snap it with primitives::quantize)");
  return k;
}

std::uint32_t count32(std::size_t n) {
  STRAHLER_ASSERT(n <= std::numeric_limits<std::uint32_t>::max(), "a world count exceeds 2^32");
  return static_cast<std::uint32_t>(n);
}

std::uint32_t riverTypeCode(primitives::RiverType type) {
  const auto code = static_cast<std::uint32_t>(type);
  STRAHLER_ASSERT(code <= static_cast<std::uint32_t>(primitives::RiverType::kDelta),
                  "a river type is out of range");
  return code;
}

/// Appends each value minus the previous one of the column.
class DeltaColumn {
public:
  explicit DeltaColumn(Int64Column* out) : out_(out) {}
  void add(std::int64_t k) {
    out_->Add(k - previous_);
    previous_ = k;
  }

private:
  Int64Column* out_;
  std::int64_t previous_ = 0;
};

void encodeLand(const geometry::MultiPolygon& land, v1::Land& out) {
  DeltaColumn x(out.mutable_x());
  DeltaColumn y(out.mutable_y());
  const auto addRing = [&](const geometry::Ring& ring) {
    STRAHLER_ASSERT(ring.size() >= 3, "a land ring has fewer than 3 vertices");
    out.add_ring_vertex_counts(count32(ring.size()));
    for (const geometry::Vec2 p : ring) {
      x.add(quanta(p.x, Quantum::kPosition));
      y.add(quanta(p.y, Quantum::kPosition));
    }
  };
  for (const geometry::Polygon& polygon : land) {
    out.add_polygon_ring_counts(count32(1 + polygon.holes.size()));
    addRing(polygon.outer);
    for (const geometry::Ring& hole : polygon.holes)
      addRing(hole);
  }
}

struct NodeQuanta {
  std::int64_t x = 0;
  std::int64_t y = 0;
  std::int64_t z = 0;
};

void encodeNodes(const WorldData& world, v1::Network& out) {
  const auto& nodes = world.network.nodes;
  std::vector<NodeQuanta> q(nodes.size());
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const network::RiverNode& node = nodes[i];
    q[i] = {quanta(node.position.x, Quantum::kPosition),
            quanta(node.position.y, Quantum::kPosition),
            quanta(node.elevation, Quantum::kElevation)};
    const bool root = !node.parent.valid();
    STRAHLER_ASSERT(root || node.parent.index() < i, "a node's parent does not come before it");
    NodeQuanta reference = root ? NodeQuanta{} : q[node.parent.index()];
    if (root && i > 0)
      reference = {q[i - 1].x, q[i - 1].y, 0};
    out.add_parent_offset(root ? 0 : count32(i - node.parent.index()));
    out.add_x(q[i].x - reference.x);
    out.add_y(q[i].y - reference.y);
    out.add_elevation(q[i].z - reference.z);
    out.add_priority(node.priority);
    out.add_strahler(node.strahler);
    out.add_flow(quanta(world.flow[i], Quantum::kFlow));
    out.add_river_type(riverTypeCode(world.riverTypes[i]));
  }
}

/// The reader rebuilds children (in id order) and tree indices: they must equal ours.
void checkDerivedLinks(const network::RiverNetwork& net,
                       const std::vector<std::uint32_t>& mouthOf) {
  std::vector<std::size_t> childrenSeen(net.nodes.size(), 0);
  for (std::size_t i = 0; i < net.nodes.size(); ++i) {
    const network::RiverNode& node = net.nodes[i];
    if (!node.parent.valid()) {
      STRAHLER_ASSERT(mouthOf[i] != kNoMouth, "a node without a parent is not a mouth");
      STRAHLER_ASSERT(node.tree == mouthOf[i], "a mouth node's tree is not its mouth index");
      continue;
    }
    const network::RiverNode& parent = net.nodes[node.parent.index()];
    STRAHLER_ASSERT(node.tree == parent.tree, "a node's tree differs from its parent's");
    std::size_t& seen = childrenSeen[node.parent.index()];
    STRAHLER_ASSERT(seen < parent.children.size() &&
                        parent.children[seen] == network::NodeId(count32(i)),
                    "children are not the nodes draining into it in increasing id order");
    ++seen;
  }
  for (std::size_t i = 0; i < net.nodes.size(); ++i)
    STRAHLER_ASSERT(childrenSeen[i] == net.nodes[i].children.size(),
                    "a node lists a child that does not drain into it");
}

void encodeMouths(const network::RiverNetwork& net, v1::Network& out) {
  std::vector<std::uint32_t> mouthOf(net.nodes.size(), kNoMouth);
  for (std::size_t m = 0; m < net.mouths.size(); ++m) {
    const network::Mouth& mouth = net.mouths[m];
    STRAHLER_ASSERT(mouth.node.valid() && mouth.node.index() < net.nodes.size(),
                    "a mouth names no node");
    STRAHLER_ASSERT(!net.node(mouth.node).parent.valid(), "a mouth node has a parent");
    STRAHLER_ASSERT(mouthOf[mouth.node.index()] == kNoMouth, "two mouths share a node");
    STRAHLER_ASSERT(std::isfinite(mouth.inward.x) && std::isfinite(mouth.inward.y),
                    "a mouth direction is not finite");
    mouthOf[mouth.node.index()] = count32(m);
    out.add_mouth_node(mouth.node.value);
    out.add_mouth_inward_x(mouth.inward.x);
    out.add_mouth_inward_y(mouth.inward.y);
    out.add_mouth_on_lake(mouth.onLake);
  }
  checkDerivedLinks(net, mouthOf);
}

void encodeNetwork(const WorldData& world, v1::Network& out) {
  const std::size_t n = world.network.nodes.size();
  STRAHLER_ASSERT(world.flow.size() == n && world.riverTypes.size() == n,
                  "flow and river types need one value per node");
  STRAHLER_ASSERT(std::isfinite(world.network.edgeLength), "the edge length is not finite");
  out.set_edge_length(world.network.edgeLength);
  encodeNodes(world, out);
  encodeMouths(world.network, out);
}

void encodeBlocks(const WorldData& world, v1::Blocks& out) {
  STRAHLER_ASSERT(world.blocks.size() == world.network.nodes.size(), "need one block per node");
  std::uint32_t terrainNext = 0;
  std::uint32_t riverNext = 0;
  for (const construction::BlockPrimitives& block : world.blocks) {
    STRAHLER_ASSERT(block.terrainBegin == terrainNext && block.terrainEnd >= block.terrainBegin &&
                        block.riverBegin == riverNext && block.riverEnd >= block.riverBegin,
                    "block primitive ranges are not contiguous in block order");
    out.add_terrain_count(block.terrainEnd - block.terrainBegin);
    out.add_river_count(block.riverEnd - block.riverBegin);
    terrainNext = block.terrainEnd;
    riverNext = block.riverEnd;
  }
  STRAHLER_ASSERT(terrainNext == world.terrain.size() && riverNext == world.rivers.size(),
                  "the blocks do not cover every primitive");
}

void encodeTerrain(const std::vector<primitives::TerrainPrimitive>& terrain,
                   v1::TerrainPrimitives& out) {
  DeltaColumn x(out.mutable_x());
  DeltaColumn y(out.mutable_y());
  DeltaColumn radius(out.mutable_radius());
  DeltaColumn elevation(out.mutable_elevation());
  DeltaColumn amplitude(out.mutable_amplitude());
  DeltaColumn roughness(out.mutable_roughness());
  DeltaColumn slopeX(out.mutable_slope_x());
  DeltaColumn slopeY(out.mutable_slope_y());
  for (const primitives::TerrainPrimitive& t : terrain) {
    x.add(quanta(t.center.x, Quantum::kPosition));
    y.add(quanta(t.center.y, Quantum::kPosition));
    radius.add(quanta(t.radius, Quantum::kRadius));
    elevation.add(quanta(t.elevation, Quantum::kElevation));
    amplitude.add(quanta(t.amplitude, Quantum::kElevation));
    roughness.add(quanta(t.roughness, Quantum::kRoughness));
    slopeX.add(quanta(t.slope.x, Quantum::kSlope));
    slopeY.add(quanta(t.slope.y, Quantum::kSlope));
  }
}

/// The river columns, filled one primitive at a time.
class RiverColumns {
public:
  explicit RiverColumns(v1::RiverPrimitives& out)
      : out_(out), x_(out.mutable_x()), y_(out.mutable_y()), elevation_(out.mutable_elevation()),
        widthUp_(out.mutable_width_up()), depthUp_(out.mutable_depth_up()),
        radius_(out.mutable_radius()) {}

  void add(const primitives::RiverPrimitive& river, std::size_t block, std::size_t nodeCount) {
    STRAHLER_ASSERT(river.curve.size() >= 2, "a river curve has fewer than 2 points");
    out_.add_point_count(count32(river.curve.size()));
    for (const primitives::CurvePoint& p : river.curve) {
      x_.add(quanta(p.position.x, Quantum::kPosition));
      y_.add(quanta(p.position.y, Quantum::kPosition));
      elevation_.add(quanta(p.elevation, Quantum::kElevation));
    }
    const std::int64_t widthUp = quanta(river.widthUp, Quantum::kRadius);
    const std::int64_t depthUp = quanta(river.depthUp, Quantum::kElevation);
    widthUp_.add(widthUp);
    out_.add_width_down(quanta(river.widthDown, Quantum::kRadius) - widthUp);
    depthUp_.add(depthUp);
    out_.add_depth_down(quanta(river.depthDown, Quantum::kElevation) - depthUp);
    radius_.add(quanta(river.radius, Quantum::kRadius));
    out_.add_type(riverTypeCode(river.type));
    STRAHLER_ASSERT(!river.node.valid() || river.node.index() < nodeCount,
                    "a river primitive names a node that does not exist");
    const std::int64_t id = river.node.valid() ? std::int64_t{river.node.value} + 1 : 0;
    out_.add_node(id - static_cast<std::int64_t>(block + 1));
  }

private:
  v1::RiverPrimitives& out_;
  DeltaColumn x_, y_, elevation_, widthUp_, depthUp_, radius_;
};

void encodeRivers(const WorldData& world, v1::RiverPrimitives& out) {
  RiverColumns columns(out);
  for (std::size_t b = 0; b < world.blocks.size(); ++b)
    for (std::uint32_t r = world.blocks[b].riverBegin; r < world.blocks[b].riverEnd; ++r)
      columns.add(world.rivers[r], b, world.network.nodes.size());
}

void encodeHeader(const WorldData& world, v1::World& out) {
  out.set_format_version(world.relief.empty() ? kWorldFormatVersionWithoutRelief
                                              : kWorldFormatVersion);
  out.set_generator_version(world.generatorVersion);
  out.set_cache_key(world.cacheKey);
  out.set_name(world.name);
  out.set_params_json(input::canonicalJson(world.params));
  const geometry::Vec2 c = world.projectionCenter;
  STRAHLER_ASSERT(std::abs(c.x) <= 180.0 && std::abs(c.y) <= 90.0,
                  "the projection centre is not a (lon, lat) in degrees");
  out.set_projection_lon(c.x);
  out.set_projection_lat(c.y);
  // world.stageSeconds is left out: timings differ from run to run, and a world file must be
  // the same bytes for the same inputs (stage_times is only read, from older files).
}

} // namespace

v1::World toProto(const WorldData& world) {
  v1::World message;
  encodeHeader(world, message);
  encodeLand(world.land, *message.mutable_land());
  encodeNetwork(world, *message.mutable_network());
  encodeBlocks(world, *message.mutable_blocks());
  encodeTerrain(world.terrain, *message.mutable_terrain());
  encodeRivers(world, *message.mutable_rivers());
  if (!world.features.empty()) // absent otherwise: the same bytes as before features existed
    encodeFeatures(world.features, *message.mutable_features());
  if (!world.relief.empty())
    encodeRelief(world.relief, *message.mutable_relief());
  return message;
}

} // namespace strahler::store::detail
