#include "corsica_drawn_features.h"
#include "result_matchers.h"
#include "test_worlds.h"

#include "strahler/geometry/distance.h"
#include "strahler/network/drawn_rivers.h"
#include "strahler/network/network_growth.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <limits>
#include <memory>

namespace strahler::network {
namespace {

using geometry::Vec2;

double polylineDistance(Vec2 p, const std::vector<Vec2>& line) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 1; i < line.size(); ++i)
    best = std::min(best, geometry::pointSegmentDistance(p, line[i - 1], line[i]));
  return best;
}

/// Corsica with the drawn features of issue 27, its land and its network, grown once.
struct DrawnCorsica {
  input::WorldSpec spec = test_support::corsicaSpec();
  std::unique_ptr<geometry::PolygonIndex> land;
  RiverNetwork network;
  double seconds = 0.0;
};

const DrawnCorsica& drawnCorsica() {
  static const std::unique_ptr<DrawnCorsica> world = [] {
    auto w = std::make_unique<DrawnCorsica>();
    w->spec.features = test_support::corsicaDrawnFeatures(w->spec);
    w->land = std::make_unique<geometry::PolygonIndex>(w->spec.land);
    const auto start = std::chrono::steady_clock::now();
    w->network = test_support::valueOf(generateNetwork(w->spec, *w->land));
    w->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return w;
  }();
  return *world;
}

/// The chain of drawn river `r` in the network: node ids from the mouth to the source, found
/// by following, from the r-th mouth, the child at each chain point's exact position.
std::vector<NodeId> chainOf(const DrawnCorsica& w, std::size_t r, const DrawnCourse& course) {
  std::vector<NodeId> chain{w.network.mouths[r].node};
  for (std::size_t k = 1; k < course.chain.size(); ++k) {
    NodeId next;
    for (NodeId c : w.network.node(chain.back()).children)
      if (w.network.node(c).position == course.node(k))
        next = c;
    if (!next.valid())
      break;
    chain.push_back(next);
  }
  return chain;
}

TEST(DrawnRivers, ChainsLieExactlyOnTheDrawnLinesFromMouthToSource) {
  const DrawnCorsica& w = drawnCorsica();
  const double e = w.spec.params.edgeLength;
  ASSERT_GE(w.network.mouths.size(), 2u);
  for (std::size_t r = 0; r < w.spec.features.rivers.size(); ++r) {
    const input::RiverFeature& river = w.spec.features.rivers[r];
    const auto course = drawnCourse(river, *w.land, w.spec.params);
    ASSERT_TRUE(course.has_value());
    const std::vector<NodeId> chain = chainOf(w, r, *course);
    ASSERT_EQ(chain.size(), course->chain.size()) << river.name;
    // The mouth is a mouth, at the drawn last point (on the coast within 0.2 m).
    const RiverNode& mouth = w.network.node(chain.front());
    EXPECT_FALSE(mouth.parent.valid());
    EXPECT_LT(distance(mouth.position, river.line.back()), 1.0) << river.name;
    // The source is the drawn first point, exactly.
    EXPECT_EQ(w.network.node(chain.back()).position, river.line.front()) << river.name;
    double previousArc = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < chain.size(); ++k) {
      const RiverNode& n = w.network.node(chain[k]);
      // On the line within 1 cm (the mouth's last segment moved by its 0.2 m snap).
      EXPECT_LT(polylineDistance(n.position, course->line), 0.01) << river.name << " " << k;
      EXPECT_LT(polylineDistance(n.position, river.line), 0.25) << river.name << " " << k;
      // In order, every e along the line from the mouth; the last step between e/2 and 1.5 e.
      EXPECT_LT(course->chain[k], previousArc);
      if (k > 0) {
        const double step = previousArc - course->chain[k];
        if (k + 1 < chain.size())
          EXPECT_NEAR(step, e, 1e-6);
        else
          EXPECT_TRUE(step >= 0.5 * e && step < 1.5 * e) << step;
        EXPECT_GT(n.elevation, w.network.node(chain[k - 1]).elevation);
        EXPECT_GE(n.priority, w.spec.params.maxPriority);
      }
      previousArc = course->chain[k];
    }
    // The grammar grew tributaries into the chain.
    std::size_t tributaries = 0;
    for (std::size_t k = 0; k + 1 < chain.size(); ++k)
      tributaries += w.network.node(chain[k]).children.size() - 1;
    EXPECT_GT(tributaries, chain.size() / 4) << river.name;
  }
}

TEST(DrawnRivers, NoEdgeCrossesARidgeOrComesNearADrawnRiver) {
  const DrawnCorsica& w = drawnCorsica();
  const input::Params& params = w.spec.params;
  std::vector<std::vector<NodeId>> chains;
  std::vector<DrawnCourse> courses;
  std::vector<int> riverOf(w.network.nodes.size(), -1);
  for (std::size_t r = 0; r < w.spec.features.rivers.size(); ++r) {
    courses.push_back(*drawnCourse(w.spec.features.rivers[r], *w.land, params));
    for (NodeId id : chainOf(w, r, courses.back()))
      riverOf[id.index()] = static_cast<int>(r);
  }
  std::size_t checked = 0, ridgeCrossings = 0, tooNear = 0, riverCrossings = 0;
  for (std::uint32_t i = 0; i < w.network.nodes.size(); ++i) {
    const RiverNode& n = w.network.nodes[i];
    if (!n.parent.valid())
      continue;
    const Vec2 a = w.network.node(n.parent).position, b = n.position;
    for (const input::RidgeFeature& ridge : w.spec.features.ridges)
      for (std::size_t k = 1; k < ridge.line.size(); ++k)
        ridgeCrossings += geometry::segmentsIntersect(a, b, ridge.line[k - 1], ridge.line[k]);
    const int parentRiver = riverOf[n.parent.index()];
    if (riverOf[i] >= 0 && riverOf[i] == parentRiver)
      continue; // an edge of a chain
    ++checked;
    for (std::size_t r = 0; r < courses.size(); ++r) {
      const std::vector<Vec2>& line = courses[r].line;
      for (std::size_t k = 1; k < line.size(); ++k) {
        if (parentRiver == int(r)) { // a tributary leaving the drawn river at its parent
          riverCrossings +=
              geometry::segmentsIntersect(geometry::lerp(a, b, 0.1), b, line[k - 1], line[k]);
        } else {
          tooNear += geometry::segmentSegmentDistance(a, b, line[k - 1], line[k]) <= params.sigma;
        }
      }
    }
  }
  EXPECT_GT(checked, 5000u);
  EXPECT_EQ(ridgeCrossings, 0u);
  EXPECT_EQ(riverCrossings, 0u);
  EXPECT_EQ(tooNear, 0u);
}

TEST(DrawnRivers, GrowthTimeWithFeaturesIsReported) {
  const DrawnCorsica& w = drawnCorsica();
  const input::WorldSpec plain = test_support::corsicaSpec();
  const auto start = std::chrono::steady_clock::now();
  const RiverNetwork without = test_support::valueOf(generateNetwork(plain, *w.land));
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("Corsica network: %.3f s with features (%zu nodes), %.3f s without (%zu nodes)\n",
              w.seconds, w.network.nodes.size(), seconds, without.nodes.size());
  EXPECT_GT(w.network.nodes.size(), without.nodes.size() * 9 / 10);
}

TEST(DrawnRivers, MouthsFacingADrawnMountainRankFirst) {
  input::WorldSpec spec = test_support::corsicaSpec();
  spec.features.mountains = test_support::corsicaDrawnFeatures(spec).mountains;
  const geometry::PolygonIndex land(spec.land);
  const std::vector<MouthSite> mouths = test_support::valueOf(placeMouths(spec, land));
  const auto faces = [&](const MouthSite& m) {
    for (const input::MountainFeature& f : spec.features.mountains)
      if (dot(normalize(f.position - m.position), m.inward) >= std::cos(std::numbers::pi / 6.0))
        return true;
    return false;
  };
  int lowestFacing = spec.params.maxPriority, highestOther = 0;
  std::size_t facing = 0;
  for (const MouthSite& m : mouths) {
    if (m.onLake)
      continue;
    if (faces(m)) {
      ++facing;
      lowestFacing = std::min(lowestFacing, m.priority);
    } else {
      highestOther = std::max(highestOther, m.priority);
    }
  }
  EXPECT_GT(facing, 3u);
  EXPECT_LT(facing, mouths.size());
  EXPECT_GE(lowestFacing, highestOther);
  // Without mountains the ranking is by accessibility alone, and differs.
  input::WorldSpec plain = test_support::corsicaSpec();
  const std::vector<MouthSite> before = test_support::valueOf(placeMouths(plain, land));
  ASSERT_EQ(before.size(), mouths.size());
  bool differs = false;
  for (std::size_t i = 0; i < mouths.size(); ++i) {
    EXPECT_EQ(before[i].position, mouths[i].position);
    differs = differs || before[i].priority != mouths[i].priority;
  }
  EXPECT_TRUE(differs);
}

TEST(DrawnRivers, AutomaticMouthsNearADrawnMouthGiveWay) {
  const DrawnCorsica& w = drawnCorsica();
  const std::vector<MouthSite> mouths = test_support::valueOf(placeMouths(w.spec, *w.land));
  ASSERT_GE(mouths.size(), 2u);
  EXPECT_EQ(mouths[0].drawnRiver, 0);
  EXPECT_EQ(mouths[1].drawnRiver, 1);
  for (std::size_t i = 2; i < mouths.size(); ++i) {
    EXPECT_EQ(mouths[i].drawnRiver, -1);
    for (std::size_t d = 0; d < 2; ++d)
      EXPECT_GE(distance(mouths[i].position, mouths[d].position), w.spec.params.mouthSpacing);
  }
}

} // namespace
} // namespace strahler::network
