// strahler.v1.World -> WorldData. The message comes from disk, so nothing in it is trusted:
// every count is checked against the columns it claims to describe before anything is
// allocated from it, every index before it is followed, every running sum before it can
// overflow.

#include "feature_codec.h"
#include "relief_codec.h"
#include "world_proto.h"

#include "strahler/input/params.h"
#include "strahler/primitives/quantization.h"
#include "strahler/store/world_file.h"

#include <cmath>
#include <limits>
#include <optional>

namespace strahler::store::detail {
namespace {

using base::Status;
using construction::WorldData;
using primitives::Quantum;
template <class T> using Column = google::protobuf::RepeatedField<T>;

constexpr std::uint32_t kNoMouth = std::numeric_limits<std::uint32_t>::max();
constexpr std::uint32_t kMaxRiverType = static_cast<std::uint32_t>(primitives::RiverType::kDelta);

/// start + delta, unless that overflows or leaves [-kMaxQuanta, kMaxQuanta].
std::optional<std::int64_t> addDelta(std::int64_t start, std::int64_t delta) {
  std::int64_t sum = 0;
  if (__builtin_add_overflow(start, delta, &sum) || sum < -kMaxQuanta || sum > kMaxQuanta)
    return std::nullopt;
  return sum;
}

double value(std::int64_t k, double step) {
  return static_cast<double>(k) * step;
}

std::string str(std::uint64_t n) {
  return std::to_string(n);
}

/// Sum of a count column (cannot overflow: a column has fewer than 2^31 entries).
std::uint64_t total(const Column<std::uint32_t>& counts) {
  std::uint64_t sum = 0;
  for (const std::uint32_t c : counts)
    sum += c;
  return sum;
}

/// Reads a delta-coded column as running sums.
class DeltaReader {
public:
  DeltaReader(const Column<std::int64_t>& column, std::string_view label)
      : column_(column), label_(label) {}

  /// The next absolute value, or nullopt when the running sum leaves the allowed range.
  std::optional<std::int64_t> next() {
    const auto sum = addDelta(previous_, column_[index_++]);
    if (sum)
      previous_ = *sum;
    return sum;
  }
  std::string_view label() const noexcept { return label_; }
  int lastIndex() const noexcept { return index_ - 1; }

private:
  const Column<std::int64_t>& column_;
  std::string_view label_;
  std::int64_t previous_ = 0;
  int index_ = 0;
};

struct NodeQuanta {
  std::int64_t x = 0;
  std::int64_t y = 0;
  std::int64_t z = 0;
};

class Decoder {
public:
  Decoder(const v1::World& message, std::string_view name) : m_(message), name_(name) {}

  base::Result<WorldData> run() {
    STRAHLER_RETURN_IF_ERROR(decodeHeader());
    STRAHLER_RETURN_IF_ERROR(decodeLand());
    STRAHLER_RETURN_IF_ERROR(decodeNodes());
    std::vector<std::uint32_t> mouthOf;
    STRAHLER_RETURN_IF_ERROR(decodeMouths(mouthOf));
    STRAHLER_RETURN_IF_ERROR(linkNodes(mouthOf));
    STRAHLER_RETURN_IF_ERROR(decodeBlocks());
    STRAHLER_RETURN_IF_ERROR(decodeTerrain());
    STRAHLER_RETURN_IF_ERROR(decodeRivers());
    if (m_.has_features()) {
      STRAHLER_ASSIGN_OR_RETURN(world_.features, decodeFeatures(m_.features(), name_));
    }
    if (m_.has_relief()) {
      STRAHLER_ASSIGN_OR_RETURN(world_.relief, decodeRelief(m_.relief(), name_));
    }
    return std::move(world_);
  }

private:
  base::Error corrupt(const std::string& what) const { return corruptError(name_, what); }

  Status expectSize(std::string_view column, int actual, std::size_t expected,
                    std::string_view unit) const {
    if (static_cast<std::size_t>(actual) == expected)
      return base::Ok{};
    return corrupt(std::string(column) + " has " + str(static_cast<std::size_t>(actual)) +
                   " values, expected " + str(expected) + " (" + std::string(unit) + ")");
  }

  Status outOfRange(std::string_view column, int index) const {
    return corrupt(std::string(column) + " value " + str(static_cast<std::size_t>(index)) +
                   " is out of range");
  }

  /// The next value of `reader` times `step`.
  Status read(DeltaReader& reader, double step, double& out) const {
    const auto k = reader.next();
    if (!k)
      return outOfRange(reader.label(), reader.lastIndex());
    out = value(*k, step);
    return base::Ok{};
  }

  Status checkedAdd(std::int64_t start, std::int64_t delta, std::string_view column, int index,
                    std::int64_t& out) const {
    const auto sum = addDelta(start, delta);
    if (!sum)
      return outOfRange(column, index);
    out = *sum;
    return base::Ok{};
  }

  Status riverType(std::uint32_t code, std::string_view column, int index,
                   primitives::RiverType& out) const {
    if (code > kMaxRiverType)
      return corrupt(std::string(column) + " value " + str(static_cast<std::size_t>(index)) +
                     " is river type " + str(code) + ", the largest is " + str(kMaxRiverType));
    out = static_cast<primitives::RiverType>(code);
    return base::Ok{};
  }

  Status decodeHeader();
  Status decodeStages();
  Status decodeLand();
  Status decodeRing(std::uint32_t vertices, DeltaReader& x, DeltaReader& y,
                    geometry::Ring& ring) const;
  Status decodeNodes();
  Status decodeNode(int i, std::vector<NodeQuanta>& q);
  Status decodeMouths(std::vector<std::uint32_t>& mouthOf);
  Status linkNodes(const std::vector<std::uint32_t>& mouthOf);
  Status decodeBlocks();
  Status decodeTerrain();
  Status decodeRivers();
  Status decodeRiver(int r, std::size_t block, DeltaReader* points, DeltaReader* perRiver);

  const v1::World& m_;
  std::string_view name_;
  WorldData world_;
};

Status Decoder::decodeHeader() {
  if (m_.format_version() != kWorldFormatVersion &&
      m_.format_version() != kWorldFormatVersionWithoutRelief)
    return corrupt("the payload says format version " + str(m_.format_version()) + ", not " +
                   str(kWorldFormatVersionWithoutRelief) + " or " + str(kWorldFormatVersion));
  if (m_.has_relief() && m_.format_version() != kWorldFormatVersion)
    return corrupt("an erosion residual in a world of format version " + str(m_.format_version()));
  world_.generatorVersion = m_.generator_version();
  world_.cacheKey = m_.cache_key();
  world_.name = m_.name();
  auto params = input::parseParams(m_.params_json());
  if (!params.ok())
    return corrupt("the stored params are invalid: " + params.error().message);
  world_.params = std::move(params).value();
  const double lon = m_.projection_lon();
  const double lat = m_.projection_lat();
  if (!(std::abs(lon) <= 180.0 && std::abs(lat) <= 90.0))
    return corrupt("the projection centre (" + std::to_string(lon) + ", " + std::to_string(lat) +
                   ") is not a longitude and latitude");
  world_.projectionCenter = {lon, lat};
  return decodeStages();
}

Status Decoder::decodeStages() {
  for (int i = 0; i < m_.stage_times_size(); ++i) {
    const v1::StageTime& stage = m_.stage_times(i);
    if (!std::isfinite(stage.seconds()))
      return corrupt("stage time " + str(static_cast<std::size_t>(i)) + " is not finite");
    world_.stageSeconds.push_back({stage.stage(), stage.seconds()});
  }
  return base::Ok{};
}

Status Decoder::decodeLand() {
  const v1::Land& land = m_.land();
  for (int p = 0; p < land.polygon_ring_counts_size(); ++p)
    if (land.polygon_ring_counts(p) == 0)
      return corrupt("land polygon " + str(static_cast<std::size_t>(p)) + " has no ring");
  STRAHLER_RETURN_IF_ERROR(expectSize("land.ring_vertex_counts", land.ring_vertex_counts_size(),
                                      total(land.polygon_ring_counts()), "rings of all polygons"));
  for (int r = 0; r < land.ring_vertex_counts_size(); ++r)
    if (land.ring_vertex_counts(r) < 3)
      return corrupt("land ring " + str(static_cast<std::size_t>(r)) + " has " +
                     str(land.ring_vertex_counts(r)) + " vertices, fewer than 3");
  const std::uint64_t vertices = total(land.ring_vertex_counts());
  STRAHLER_RETURN_IF_ERROR(expectSize("land.x", land.x_size(), vertices, "vertices of all rings"));
  STRAHLER_RETURN_IF_ERROR(expectSize("land.y", land.y_size(), vertices, "vertices of all rings"));
  DeltaReader x(land.x(), "land.x");
  DeltaReader y(land.y(), "land.y");
  int ring = 0;
  world_.land.resize(static_cast<std::size_t>(land.polygon_ring_counts_size()));
  for (int p = 0; p < land.polygon_ring_counts_size(); ++p) {
    geometry::Polygon& polygon = world_.land[static_cast<std::size_t>(p)];
    polygon.holes.resize(land.polygon_ring_counts(p) - 1);
    STRAHLER_RETURN_IF_ERROR(decodeRing(land.ring_vertex_counts(ring++), x, y, polygon.outer));
    for (geometry::Ring& hole : polygon.holes)
      STRAHLER_RETURN_IF_ERROR(decodeRing(land.ring_vertex_counts(ring++), x, y, hole));
  }
  return base::Ok{};
}

Status Decoder::decodeRing(std::uint32_t vertices, DeltaReader& x, DeltaReader& y,
                           geometry::Ring& ring) const {
  ring.resize(vertices);
  for (geometry::Vec2& p : ring) {
    STRAHLER_RETURN_IF_ERROR(read(x, Quantum::kPosition, p.x));
    STRAHLER_RETURN_IF_ERROR(read(y, Quantum::kPosition, p.y));
  }
  return base::Ok{};
}

Status Decoder::decodeNodes() {
  const v1::Network& net = m_.network();
  if (!std::isfinite(net.edge_length()))
    return corrupt("the edge length is not finite");
  world_.network.edgeLength = net.edge_length();
  const auto n = static_cast<std::size_t>(net.parent_offset_size());
  const std::string_view unit = "one per node";
  STRAHLER_RETURN_IF_ERROR(expectSize("network.x", net.x_size(), n, unit));
  STRAHLER_RETURN_IF_ERROR(expectSize("network.y", net.y_size(), n, unit));
  STRAHLER_RETURN_IF_ERROR(expectSize("network.elevation", net.elevation_size(), n, unit));
  STRAHLER_RETURN_IF_ERROR(expectSize("network.priority", net.priority_size(), n, unit));
  STRAHLER_RETURN_IF_ERROR(expectSize("network.strahler", net.strahler_size(), n, unit));
  STRAHLER_RETURN_IF_ERROR(expectSize("network.flow", net.flow_size(), n, unit));
  STRAHLER_RETURN_IF_ERROR(expectSize("network.river_type", net.river_type_size(), n, unit));
  world_.network.nodes.resize(n);
  world_.flow.resize(n);
  world_.riverTypes.resize(n);
  std::vector<NodeQuanta> q(n);
  for (int i = 0; i < static_cast<int>(n); ++i)
    STRAHLER_RETURN_IF_ERROR(decodeNode(i, q));
  return base::Ok{};
}

Status Decoder::decodeNode(int i, std::vector<NodeQuanta>& q) {
  const v1::Network& net = m_.network();
  const auto index = static_cast<std::size_t>(i);
  const std::uint32_t offset = net.parent_offset(i);
  if (offset > index)
    return corrupt("node " + str(index) + " has parent offset " + str(offset) +
                   ", which points before node 0");
  network::RiverNode& node = world_.network.nodes[index];
  NodeQuanta reference = offset > 0 ? q[index - offset] : NodeQuanta{};
  if (offset == 0 && index > 0)
    reference = {q[index - 1].x, q[index - 1].y, 0};
  STRAHLER_RETURN_IF_ERROR(checkedAdd(reference.x, net.x(i), "network.x", i, q[index].x));
  STRAHLER_RETURN_IF_ERROR(checkedAdd(reference.y, net.y(i), "network.y", i, q[index].y));
  STRAHLER_RETURN_IF_ERROR(
      checkedAdd(reference.z, net.elevation(i), "network.elevation", i, q[index].z));
  node.position = {value(q[index].x, Quantum::kPosition), value(q[index].y, Quantum::kPosition)};
  node.elevation = value(q[index].z, Quantum::kElevation);
  node.parent = offset > 0 ? network::NodeId(static_cast<std::uint32_t>(index - offset))
                           : network::NodeId::invalid();
  node.priority = net.priority(i);
  node.strahler = net.strahler(i);
  std::int64_t flow = 0;
  STRAHLER_RETURN_IF_ERROR(checkedAdd(0, net.flow(i), "network.flow", i, flow));
  world_.flow[index] = value(flow, Quantum::kFlow);
  return riverType(net.river_type(i), "network.river_type", i, world_.riverTypes[index]);
}

Status Decoder::decodeMouths(std::vector<std::uint32_t>& mouthOf) {
  const v1::Network& net = m_.network();
  const auto count = static_cast<std::size_t>(net.mouth_node_size());
  STRAHLER_RETURN_IF_ERROR(
      expectSize("network.mouth_inward_x", net.mouth_inward_x_size(), count, "one per mouth"));
  STRAHLER_RETURN_IF_ERROR(
      expectSize("network.mouth_inward_y", net.mouth_inward_y_size(), count, "one per mouth"));
  STRAHLER_RETURN_IF_ERROR(
      expectSize("network.mouth_on_lake", net.mouth_on_lake_size(), count, "one per mouth"));
  auto& nodes = world_.network.nodes;
  mouthOf.assign(nodes.size(), kNoMouth);
  for (int m = 0; m < net.mouth_node_size(); ++m) {
    const std::string mouth = "mouth " + str(static_cast<std::size_t>(m));
    const std::uint32_t node = net.mouth_node(m);
    if (node >= nodes.size())
      return corrupt(mouth + " names node " + str(node) + " of " + str(nodes.size()));
    if (nodes[node].parent.valid())
      return corrupt(mouth + " names node " + str(node) + ", which has a parent");
    if (mouthOf[node] != kNoMouth)
      return corrupt(mouth + " names node " + str(node) + ", as mouth " + str(mouthOf[node]) +
                     " does");
    const geometry::Vec2 inward{net.mouth_inward_x(m), net.mouth_inward_y(m)};
    if (!std::isfinite(inward.x) || !std::isfinite(inward.y))
      return corrupt(mouth + " has a non-finite inward direction");
    mouthOf[node] = static_cast<std::uint32_t>(m);
    world_.network.mouths.push_back({network::NodeId(node), inward, net.mouth_on_lake(m)});
  }
  return base::Ok{};
}

Status Decoder::linkNodes(const std::vector<std::uint32_t>& mouthOf) {
  auto& nodes = world_.network.nodes;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    network::RiverNode& node = nodes[i];
    if (!node.parent.valid()) {
      if (mouthOf[i] == kNoMouth)
        return corrupt("node " + str(i) + " has no parent but is not a mouth");
      node.tree = mouthOf[i];
      continue;
    }
    network::RiverNode& parent = nodes[node.parent.index()];
    node.tree = parent.tree;
    parent.children.push_back(network::NodeId(static_cast<std::uint32_t>(i)));
  }
  return base::Ok{};
}

Status Decoder::decodeBlocks() {
  const v1::Blocks& blocks = m_.blocks();
  const std::size_t n = world_.network.nodes.size();
  STRAHLER_RETURN_IF_ERROR(
      expectSize("blocks.terrain_count", blocks.terrain_count_size(), n, "one block per node"));
  STRAHLER_RETURN_IF_ERROR(
      expectSize("blocks.river_count", blocks.river_count_size(), n, "one block per node"));
  STRAHLER_RETURN_IF_ERROR(expectSize("terrain.x", m_.terrain().x_size(),
                                      total(blocks.terrain_count()), "sum of the block counts"));
  STRAHLER_RETURN_IF_ERROR(expectSize("rivers.point_count", m_.rivers().point_count_size(),
                                      total(blocks.river_count()), "sum of the block counts"));
  // Both sums equal a column size (< 2^31): the running offsets fit in 32 bits.
  world_.blocks.resize(n);
  std::uint32_t terrain = 0;
  std::uint32_t rivers = 0;
  for (std::size_t b = 0; b < n; ++b) {
    const int i = static_cast<int>(b);
    world_.blocks[b] = {terrain, terrain + blocks.terrain_count(i), rivers,
                        rivers + blocks.river_count(i)};
    terrain += blocks.terrain_count(i);
    rivers += blocks.river_count(i);
  }
  return base::Ok{};
}

Status Decoder::decodeTerrain() {
  const v1::TerrainPrimitives& t = m_.terrain();
  const auto n = static_cast<std::size_t>(t.x_size());
  const std::string_view unit = "one per terrain primitive";
  STRAHLER_RETURN_IF_ERROR(expectSize("terrain.y", t.y_size(), n, unit));
  STRAHLER_RETURN_IF_ERROR(expectSize("terrain.radius", t.radius_size(), n, unit));
  STRAHLER_RETURN_IF_ERROR(expectSize("terrain.elevation", t.elevation_size(), n, unit));
  STRAHLER_RETURN_IF_ERROR(expectSize("terrain.amplitude", t.amplitude_size(), n, unit));
  STRAHLER_RETURN_IF_ERROR(expectSize("terrain.roughness", t.roughness_size(), n, unit));
  STRAHLER_RETURN_IF_ERROR(expectSize("terrain.slope_x", t.slope_x_size(), n, unit));
  STRAHLER_RETURN_IF_ERROR(expectSize("terrain.slope_y", t.slope_y_size(), n, unit));
  DeltaReader x(t.x(), "terrain.x");
  DeltaReader y(t.y(), "terrain.y");
  DeltaReader radius(t.radius(), "terrain.radius");
  DeltaReader elevation(t.elevation(), "terrain.elevation");
  DeltaReader amplitude(t.amplitude(), "terrain.amplitude");
  DeltaReader roughness(t.roughness(), "terrain.roughness");
  DeltaReader slopeX(t.slope_x(), "terrain.slope_x");
  DeltaReader slopeY(t.slope_y(), "terrain.slope_y");
  world_.terrain.resize(n);
  for (primitives::TerrainPrimitive& p : world_.terrain) {
    STRAHLER_RETURN_IF_ERROR(read(x, Quantum::kPosition, p.center.x));
    STRAHLER_RETURN_IF_ERROR(read(y, Quantum::kPosition, p.center.y));
    STRAHLER_RETURN_IF_ERROR(read(radius, Quantum::kRadius, p.radius));
    STRAHLER_RETURN_IF_ERROR(read(elevation, Quantum::kElevation, p.elevation));
    STRAHLER_RETURN_IF_ERROR(read(amplitude, Quantum::kElevation, p.amplitude));
    STRAHLER_RETURN_IF_ERROR(read(roughness, Quantum::kRoughness, p.roughness));
    STRAHLER_RETURN_IF_ERROR(read(slopeX, Quantum::kSlope, p.slope.x));
    STRAHLER_RETURN_IF_ERROR(read(slopeY, Quantum::kSlope, p.slope.y));
  }
  return base::Ok{};
}

Status Decoder::decodeRivers() {
  const v1::RiverPrimitives& r = m_.rivers();
  const auto n = static_cast<std::size_t>(r.point_count_size());
  const std::string_view unit = "one per river primitive";
  STRAHLER_RETURN_IF_ERROR(expectSize("rivers.width_up", r.width_up_size(), n, unit));
  STRAHLER_RETURN_IF_ERROR(expectSize("rivers.width_down", r.width_down_size(), n, unit));
  STRAHLER_RETURN_IF_ERROR(expectSize("rivers.depth_up", r.depth_up_size(), n, unit));
  STRAHLER_RETURN_IF_ERROR(expectSize("rivers.depth_down", r.depth_down_size(), n, unit));
  STRAHLER_RETURN_IF_ERROR(expectSize("rivers.radius", r.radius_size(), n, unit));
  STRAHLER_RETURN_IF_ERROR(expectSize("rivers.type", r.type_size(), n, unit));
  STRAHLER_RETURN_IF_ERROR(expectSize("rivers.node", r.node_size(), n, unit));
  for (int i = 0; i < r.point_count_size(); ++i)
    if (r.point_count(i) < 2)
      return corrupt("river primitive " + str(static_cast<std::size_t>(i)) + " has " +
                     str(r.point_count(i)) + " curve points, fewer than 2");
  const std::uint64_t points = total(r.point_count());
  STRAHLER_RETURN_IF_ERROR(expectSize("rivers.x", r.x_size(), points, "sum of the point counts"));
  STRAHLER_RETURN_IF_ERROR(expectSize("rivers.y", r.y_size(), points, "sum of the point counts"));
  STRAHLER_RETURN_IF_ERROR(
      expectSize("rivers.elevation", r.elevation_size(), points, "sum of the point counts"));
  DeltaReader pointColumns[] = {
      {r.x(), "rivers.x"}, {r.y(), "rivers.y"}, {r.elevation(), "rivers.elevation"}};
  DeltaReader riverColumns[] = {{r.width_up(), "rivers.width_up"},
                                {r.depth_up(), "rivers.depth_up"},
                                {r.radius(), "rivers.radius"}};
  world_.rivers.resize(n);
  for (std::size_t b = 0; b < world_.blocks.size(); ++b)
    for (std::uint32_t i = world_.blocks[b].riverBegin; i < world_.blocks[b].riverEnd; ++i)
      STRAHLER_RETURN_IF_ERROR(decodeRiver(static_cast<int>(i), b, pointColumns, riverColumns));
  return base::Ok{};
}

Status Decoder::decodeRiver(int r, std::size_t block, DeltaReader* points, DeltaReader* perRiver) {
  const v1::RiverPrimitives& m = m_.rivers();
  primitives::RiverPrimitive& river = world_.rivers[static_cast<std::size_t>(r)];
  river.curve.resize(m.point_count(r));
  for (primitives::CurvePoint& p : river.curve) {
    STRAHLER_RETURN_IF_ERROR(read(points[0], Quantum::kPosition, p.position.x));
    STRAHLER_RETURN_IF_ERROR(read(points[1], Quantum::kPosition, p.position.y));
    STRAHLER_RETURN_IF_ERROR(read(points[2], Quantum::kElevation, p.elevation));
  }
  const auto widthUp = perRiver[0].next();
  const auto depthUp = perRiver[1].next();
  if (!widthUp)
    return outOfRange("rivers.width_up", r);
  if (!depthUp)
    return outOfRange("rivers.depth_up", r);
  std::int64_t widthDown = 0;
  std::int64_t depthDown = 0;
  STRAHLER_RETURN_IF_ERROR(
      checkedAdd(*widthUp, m.width_down(r), "rivers.width_down", r, widthDown));
  STRAHLER_RETURN_IF_ERROR(
      checkedAdd(*depthUp, m.depth_down(r), "rivers.depth_down", r, depthDown));
  river.widthUp = value(*widthUp, Quantum::kRadius);
  river.widthDown = value(widthDown, Quantum::kRadius);
  river.depthUp = value(*depthUp, Quantum::kElevation);
  river.depthDown = value(depthDown, Quantum::kElevation);
  STRAHLER_RETURN_IF_ERROR(read(perRiver[2], Quantum::kRadius, river.radius));
  STRAHLER_RETURN_IF_ERROR(riverType(m.type(r), "rivers.type", r, river.type));
  std::int64_t id = 0;
  const std::size_t nodes = world_.network.nodes.size();
  const Status node =
      checkedAdd(static_cast<std::int64_t>(block + 1), m.node(r), "rivers.node", r, id);
  if (!node.ok() || id < 0 || static_cast<std::uint64_t>(id) > nodes)
    return corrupt("river primitive " + str(static_cast<std::size_t>(r)) +
                   " names a node outside the " + str(nodes) + " of the network");
  river.node =
      id == 0 ? network::NodeId::invalid() : network::NodeId(static_cast<std::uint32_t>(id - 1));
  return base::Ok{};
}

} // namespace

base::Result<WorldData> fromProto(const v1::World& message, std::string_view name) {
  return Decoder(message, name).run();
}

} // namespace strahler::store::detail
