#include "world_fixtures.h"

#include "strahler/base/random.h"
#include "strahler/primitives/quantization.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>

namespace strahler::store::test_support {
namespace {

using construction::WorldData;
using geometry::Vec2;
using network::NodeId;
using primitives::quantize;
using primitives::Quantum;

double position(double v) {
  return quantize(v, Quantum::kPosition);
}
double elevation(double v) {
  return quantize(v, Quantum::kElevation);
}
double radius(double v) {
  return quantize(v, Quantum::kRadius);
}
Vec2 point(double x, double y) {
  return {position(x), position(y)};
}

WorldData baseWorld(std::string name, std::uint64_t seed) {
  WorldData w;
  w.name = std::move(name);
  w.cacheKey = "0123456789abcdef0123456789abcdef";
  w.generatorVersion = "0.1.0-test";
  w.params.seed = seed;
  w.params.edgeLength = 500.0;
  w.params.sigma = 400.0;
  w.projectionCenter = {9.1234567890123, 42.0987654321};
  w.stageSeconds = {{"network", 0.0123456789}, {"blocks", 1.5e-3}};
  return w;
}

/// Adds a node; parent < index; children, tree and Strahler numbers are set by finishNetwork.
void addNode(network::RiverNetwork& net, Vec2 position, double z, NodeId parent, int priority) {
  network::RiverNode node;
  node.position = position;
  node.elevation = z;
  node.parent = parent;
  node.priority = priority;
  net.nodes.push_back(node);
}

void finishNetwork(network::RiverNetwork& net) {
  std::vector<std::uint32_t> mouthOf(net.nodes.size(), 0);
  for (std::size_t m = 0; m < net.mouths.size(); ++m)
    mouthOf[net.mouths[m].node.index()] = static_cast<std::uint32_t>(m);
  for (std::size_t i = 0; i < net.nodes.size(); ++i) {
    network::RiverNode& node = net.nodes[i];
    if (!node.parent.valid()) {
      node.tree = mouthOf[i];
      continue;
    }
    net.nodes[node.parent.index()].children.push_back(NodeId(static_cast<std::uint32_t>(i)));
    node.tree = net.nodes[node.parent.index()].tree;
  }
  network::computeStrahlerNumbers(net);
}

void addPerNodeValues(WorldData& w, base::Rng& rng) {
  for (std::size_t i = 0; i < w.network.nodes.size(); ++i) {
    w.flow.push_back(quantize(rng.uniform(0.0, 60.0), Quantum::kFlow));
    w.riverTypes.push_back(static_cast<primitives::RiverType>(rng.below(4)));
  }
}

primitives::TerrainPrimitive terrainNear(Vec2 c, double z, double spread, base::Rng& rng) {
  primitives::TerrainPrimitive t;
  t.center = point(c.x + rng.uniform(-spread, spread), c.y + rng.uniform(-spread, spread));
  t.radius = radius(rng.uniform(250.0, 500.0));
  t.elevation = elevation(std::max(0.0, z + rng.uniform(-40.0, 60.0)));
  t.amplitude = elevation(rng.uniform(0.0, 40.0));
  t.roughness = quantize(rng.uniform(0.3, 0.7), Quantum::kRoughness);
  t.slope = {quantize(rng.uniform(-0.8, 0.8), Quantum::kSlope),
             quantize(rng.uniform(-0.8, 0.8), Quantum::kSlope)};
  return t;
}

/// A meandering river section from `from` (elevation zFrom) down to `to` (zTo).
primitives::RiverPrimitive riverBetween(Vec2 from, double zFrom, Vec2 to, double zTo,
                                        std::size_t points, base::Rng& rng) {
  primitives::RiverPrimitive r;
  const Vec2 normal = geometry::perpendicular(geometry::normalize(to - from));
  for (std::size_t k = 0; k < points; ++k) {
    const double t = static_cast<double>(k) / static_cast<double>(points - 1);
    const double meander = 60.0 * std::sin(t * 2.0 * std::numbers::pi) + rng.uniform(-10.0, 10.0);
    const Vec2 p = geometry::lerp(from, to, t) + normal * meander;
    r.curve.push_back({point(p.x, p.y), elevation(zFrom + (zTo - zFrom) * t)});
  }
  r.widthUp = radius(rng.uniform(2.0, 40.0));
  r.widthDown = radius(r.widthUp + rng.uniform(0.0, 5.0));
  r.depthUp = elevation(rng.uniform(0.5, 3.0));
  r.depthDown = elevation(r.depthUp + rng.uniform(0.0, 1.0));
  r.radius = radius(rng.uniform(100.0, 400.0));
  r.type = static_cast<primitives::RiverType>(rng.below(4));
  return r;
}

/// Appends block b's primitives and its BlockPrimitives entry.
void addBlock(WorldData& w, std::size_t b, std::uint32_t terrainCount, std::uint32_t riverCount,
              std::size_t points, double spread, base::Rng& rng) {
  const network::RiverNode& node = w.network.nodes[b];
  construction::BlockPrimitives block;
  block.terrainBegin = static_cast<std::uint32_t>(w.terrain.size());
  block.riverBegin = static_cast<std::uint32_t>(w.rivers.size());
  for (std::uint32_t k = 0; k < terrainCount; ++k)
    w.terrain.push_back(terrainNear(node.position, node.elevation, spread, rng));
  for (std::uint32_t k = 0; k < riverCount; ++k) {
    const bool root = !node.parent.valid();
    const Vec2 to = root ? node.position - Vec2{900.0, 0.0} : w.network.node(node.parent).position;
    const double zTo = root ? 0.0 : w.network.node(node.parent).elevation;
    w.rivers.push_back(riverBetween(node.position, node.elevation, to, zTo, points, rng));
    w.rivers.back().node = NodeId(static_cast<std::uint32_t>(b));
  }
  block.terrainEnd = static_cast<std::uint32_t>(w.terrain.size());
  block.riverEnd = static_cast<std::uint32_t>(w.rivers.size());
  w.blocks.push_back(block);
}

/// A square outline of side `side` whose edges wiggle, one vertex every `step` metres.
geometry::Ring wigglySquare(double side, double step, base::Rng& rng) {
  geometry::Ring ring;
  const Vec2 corners[] = {{0, 0}, {side, 0}, {side, side}, {0, side}};
  const auto perSide = static_cast<int>(side / step);
  for (int c = 0; c < 4; ++c) {
    const Vec2 a = corners[c];
    const Vec2 b = corners[(c + 1) % 4];
    const Vec2 inward = geometry::perpendicular(geometry::normalize(b - a));
    for (int k = 0; k < perSide; ++k) {
      const double wiggle = k == 0 ? 0.0 : rng.uniform(-20.0, 20.0);
      const Vec2 p = geometry::lerp(a, b, k / double(perSide)) + inward * wiggle;
      ring.push_back(point(p.x, p.y));
    }
  }
  return ring;
}

} // namespace

WorldData makeSmallWorld(std::uint64_t seed) {
  base::Rng rng(seed);
  WorldData w = baseWorld("small", seed);
  geometry::Polygon island;
  island.outer = {point(0, 0), point(10000, 0), point(10000, 10000), point(0, 10000)};
  island.holes.push_back(
      {point(4000, 4000), point(4000, 6000.3), point(6000, 6000), point(6000, 4000)});
  geometry::Polygon islet;
  islet.outer = {point(12000, 0), point(14000, 0), point(13000, 1500.7)};
  w.land = {island, islet};

  const int parents[] = {-1, 0, 0, -1, 3, 1, 1, 4, 2, 5, 4, 0};
  for (std::size_t i = 0; i < std::size(parents); ++i) {
    const NodeId parent =
        parents[i] < 0 ? NodeId::invalid() : NodeId(static_cast<std::uint32_t>(parents[i]));
    const Vec2 base = parent.valid() ? w.network.node(parent).position
                                     : Vec2{rng.uniform(0, 10000), rng.uniform(0, 10000)};
    const double z = parent.valid() ? w.network.node(parent).elevation + rng.uniform(1, 30) : 0.0;
    addNode(w.network, point(base.x + rng.uniform(-500, 500), base.y + rng.uniform(-500, 500)),
            elevation(z), parent, 1 + static_cast<int>(rng.below(5)));
  }
  // Mouth order differs from node order, so tree indices are not trivially node order.
  w.network.mouths = {{NodeId(3), geometry::normalize(Vec2{0.3, 0.7}), true},
                      {NodeId(0), geometry::normalize(Vec2{-1.0, 0.2}), false}};
  w.network.edgeLength = 500.0;
  finishNetwork(w.network);
  addPerNodeValues(w, rng);
  for (std::size_t b = 0; b < w.network.nodes.size(); ++b)
    addBlock(w, b, rng.below(4), rng.below(3), 2 + rng.below(5), 300.0, rng);
  if (!w.rivers.empty())
    w.rivers.back().node = NodeId::invalid();
  return w;
}

WorldData makeLargeWorld(double areaKm2, std::uint64_t seed) {
  base::Rng rng(seed);
  WorldData w = baseWorld("large", seed);
  const double side = std::sqrt(areaKm2) * 1000.0;
  w.land = {geometry::Polygon{wigglySquare(side, 125.0, rng), {}}};
  const auto cols = static_cast<std::uint32_t>(std::lround(side / 1000.0));
  for (std::uint32_t i = 0; i < cols; ++i) {
    for (std::uint32_t j = 0; j < cols; ++j) {
      // A comb of rivers: along each row, and down the first column to the mouth at (0, 0).
      const NodeId parent =
          j > 0 ? NodeId(i * cols + j - 1) : (i > 0 ? NodeId((i - 1) * cols) : NodeId::invalid());
      const double z = parent.valid() ? w.network.node(parent).elevation + rng.uniform(2, 25) : 0;
      addNode(w.network,
              point(500.0 + j * 1000.0 + rng.uniform(-150, 150),
                    500.0 + i * 1000.0 + rng.uniform(-150, 150)),
              elevation(z), parent, 1 + static_cast<int>(rng.below(5)));
    }
  }
  w.network.mouths = {{NodeId(0), Vec2{1.0, 0.0}, false}};
  w.network.edgeLength = 1000.0;
  finishNetwork(w.network);
  addPerNodeValues(w, rng);
  for (std::size_t b = 0; b < w.network.nodes.size(); ++b)
    addBlock(w, b, 10, 1, 15, 450.0, rng);
  return w;
}

::testing::AssertionResult worldsEqual(const WorldData& a, const WorldData& b) {
  const auto fail = [](const char* what) { return ::testing::AssertionFailure() << what; };
  if (a.name != b.name || a.cacheKey != b.cacheKey || a.generatorVersion != b.generatorVersion)
    return fail("name, cache key or generator version differ");
  if (!(a.params == b.params))
    return fail("params differ");
  if (!(a.projectionCenter == b.projectionCenter))
    return fail("projection centres differ");
  if (a.land.size() != b.land.size())
    return fail("land polygon counts differ");
  for (std::size_t p = 0; p < a.land.size(); ++p)
    if (a.land[p].outer != b.land[p].outer || a.land[p].holes != b.land[p].holes)
      return fail("a land polygon differs");
  const auto& na = a.network;
  const auto& nb = b.network;
  if (na.nodes.size() != nb.nodes.size() || na.edgeLength != nb.edgeLength)
    return fail("node counts or edge lengths differ");
  for (std::size_t i = 0; i < na.nodes.size(); ++i) {
    const auto& x = na.nodes[i];
    const auto& y = nb.nodes[i];
    if (!(x.position == y.position) || x.elevation != y.elevation || x.parent != y.parent ||
        x.children != y.children || x.priority != y.priority || x.strahler != y.strahler ||
        x.tree != y.tree)
      return fail("a node differs") << " (node " << i << ")";
  }
  if (na.mouths.size() != nb.mouths.size())
    return fail("mouth counts differ");
  for (std::size_t m = 0; m < na.mouths.size(); ++m)
    if (na.mouths[m].node != nb.mouths[m].node || !(na.mouths[m].inward == nb.mouths[m].inward) ||
        na.mouths[m].onLake != nb.mouths[m].onLake)
      return fail("a mouth differs") << " (mouth " << m << ")";
  if (a.flow != b.flow || a.riverTypes != b.riverTypes)
    return fail("flow or river types differ");
  if (a.terrain != b.terrain)
    return fail("terrain primitives differ");
  if (a.rivers != b.rivers)
    return fail("river primitives differ");
  if (a.blocks != b.blocks)
    return fail("blocks differ");
  if (!(a.features == b.features))
    return fail("features differ");
  // stageSeconds is not compared: world files do not store timings.
  return ::testing::AssertionSuccess();
}

std::string scratchDir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::filesystem::path dir = std::filesystem::path(STRAHLER_BINARY_DIR) / "test_scratch" /
                                    "store" /
                                    (std::string(info->test_suite_name()) + "." + info->name());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

std::vector<std::string> listDir(const std::string& dir) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

} // namespace strahler::store::test_support
