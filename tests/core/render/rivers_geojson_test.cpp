#include "result_matchers.h"
#include "test_worlds.h"

#include "strahler/construction/world_builder.h"
#include "strahler/geometry/distance.h"
#include "strahler/geometry/grid_index.h"
#include "strahler/render/rivers_geojson.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <limits>
#include <set>
#include <string>

namespace strahler::render {
namespace {

using geometry::Vec2;
using nlohmann::json;

// Coordinates carry 6 decimals of a degree: at most ~0.06 m off along each axis.
constexpr double kCoordinateSlack = 0.2;

struct GeneratedWorld {
  input::WorldSpec spec;
  construction::WorldData data;
};

const GeneratedWorld& island() {
  static const GeneratedWorld world = [] {
    GeneratedWorld w{test_support::defaultIslandSpec(), {}};
    auto data = construction::generateWorldData(w.spec, "rivers-geojson-test");
    w.data = test_support::valueOf(std::move(data));
    return w;
  }();
  return world;
}

/// Nearest-point queries over a set of points or segments (brute force within grid cells).
class NearIndex {
public:
  explicit NearIndex(const geometry::Aabb& bounds) : grid_(bounds.expanded(500.0), 250.0) {}

  void addSegment(Vec2 a, Vec2 b) {
    geometry::Aabb box;
    box.add(a);
    box.add(b);
    grid_.insert(box, static_cast<std::uint32_t>(segments_.size()));
    segments_.push_back({a, b});
  }
  /// Distance from p to the nearest segment within `reach`, else infinity.
  double distance(Vec2 p, double reach) const {
    geometry::Aabb box;
    box.add(p);
    double best = std::numeric_limits<double>::infinity();
    grid_.query(box.expanded(reach), [&](std::uint32_t i) {
      best = std::min(best,
                      geometry::pointSegmentDistance(p, segments_[i].first, segments_[i].second));
      return true;
    });
    return best;
  }

private:
  geometry::GridIndex grid_;
  std::vector<std::pair<Vec2, Vec2>> segments_;
};

geometry::Aabb landBounds(const construction::WorldData& data) {
  geometry::Aabb box;
  for (const geometry::Polygon& p : data.land)
    box.add(geometry::bounds(p.outer));
  return box;
}

std::vector<Vec2> localLine(const json& feature, const geometry::LocalProjection& projection) {
  std::vector<Vec2> line;
  for (const json& c : feature["geometry"]["coordinates"])
    line.push_back(projection.forward({c[0].get<double>(), c[1].get<double>()}));
  return line;
}

TEST(RiversGeoJson, LinesAreVerticesOfTheRiverPrimitivesCurves) {
  const GeneratedWorld& w = island();
  const json rivers = json::parse(riversGeoJson(w.data, w.spec.projection));
  // Every vertex of every curve, as a zero-length segment; and the straight graph edges.
  NearIndex vertices(landBounds(w.data)), edges(landBounds(w.data));
  for (const primitives::RiverPrimitive& r : w.data.rivers)
    for (const primitives::CurvePoint& c : r.curve)
      vertices.addSegment(c.position, c.position);
  for (const network::RiverNode& n : w.data.network.nodes)
    if (n.parent.valid())
      edges.addSegment(w.data.network.node(n.parent).position, n.position);

  std::size_t lines = 0, points = 0;
  double farthestFromEdges = 0.0;
  for (const json& f : rivers["features"]) {
    if (f["geometry"]["type"] != "LineString")
      continue;
    ++lines;
    const std::vector<Vec2> line = localLine(f, w.spec.projection);
    ASSERT_GE(line.size(), 2u);
    points += line.size();
    for (Vec2 p : line) {
      ASSERT_LT(vertices.distance(p, 1.0), kCoordinateSlack) << "not on a river curve";
      farthestFromEdges = std::max(farthestFromEdges, edges.distance(p, 1000.0));
    }
  }
  EXPECT_GT(lines, 100u);
  // The lines meander away from the straight edges between nodes, and hold more points.
  EXPECT_GT(farthestFromEdges, 20.0);
  EXPECT_GT(points, w.data.network.edgeCount() + lines);
}

TEST(RiversGeoJson, LinesStartAndEndAtNodes) {
  const GeneratedWorld& w = island();
  const json rivers = json::parse(riversGeoJson(w.data, w.spec.projection));
  NearIndex nodes(landBounds(w.data));
  for (const network::RiverNode& n : w.data.network.nodes)
    nodes.addSegment(n.position, n.position);
  for (const json& f : rivers["features"]) {
    if (f["geometry"]["type"] != "LineString")
      continue;
    const std::vector<Vec2> line = localLine(f, w.spec.projection);
    ASSERT_LT(nodes.distance(line.front(), 1.0), kCoordinateSlack);
    ASSERT_LT(nodes.distance(line.back(), 1.0), kCoordinateSlack);
  }
}

TEST(RiversGeoJson, EveryLineHasItsOrderFlowTypeAndChannelWidth) {
  const GeneratedWorld& w = island();
  const json rivers = json::parse(riversGeoJson(w.data, w.spec.projection));
  const std::set<std::string> types{"B", "E", "D", "D-delta"};
  std::size_t mouths = 0;
  for (const json& f : rivers["features"]) {
    const json& p = f["properties"];
    if (f["geometry"]["type"] == "Point") {
      ++mouths;
      EXPECT_TRUE(p["mouth"].get<bool>());
      EXPECT_GE(p["priority"].get<int>(), 1);
      continue;
    }
    EXPECT_GE(p["strahler"].get<int>(), 1);
    EXPECT_TRUE(types.contains(p["rosgen"].get<std::string>())) << p["rosgen"];
    EXPECT_GT(p["flow"].get<double>(), 0.0);
    const double up = p["widthUpM"].get<double>(), down = p["widthDownM"].get<double>();
    EXPECT_GT(up, 0.0);
    EXPECT_GE(down, up) << "channels widen downstream";
    EXPECT_GE(p["elevationUp"].get<double>(), p["elevationDown"].get<double>());
    EXPECT_TRUE(p.contains("tree"));
  }
  EXPECT_EQ(mouths, w.data.network.mouths.size());
}

TEST(RiversGeoJson, WithoutPrimitivesLinesFollowTheGraphEdges) {
  GeneratedWorld w = island();
  w.data.rivers.clear();
  const json rivers = json::parse(riversGeoJson(w.data, w.spec.projection));
  NearIndex nodes(landBounds(w.data));
  for (const network::RiverNode& n : w.data.network.nodes)
    nodes.addSegment(n.position, n.position);
  std::size_t lines = 0;
  for (const json& f : rivers["features"]) {
    if (f["geometry"]["type"] != "LineString")
      continue;
    ++lines;
    for (Vec2 p : localLine(f, w.spec.projection))
      ASSERT_LT(nodes.distance(p, 1.0), kCoordinateSlack);
  }
  EXPECT_GT(lines, 100u);
}

} // namespace
} // namespace strahler::render
