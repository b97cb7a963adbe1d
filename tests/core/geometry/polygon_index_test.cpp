#include "strahler/base/random.h"
#include "strahler/geometry/distance.h"
#include "strahler/geometry/polygon_index.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace strahler::geometry {
namespace {

/// A wiggly star-shaped island with a lake, plus a small islet.
MultiPolygon wigglyLand() {
  Polygon island;
  for (int i = 0; i < 400; ++i) {
    const double t = 2 * std::numbers::pi * i / 400;
    const double r = 10000 * (1 + 0.3 * std::sin(5 * t) + 0.1 * std::cos(17 * t));
    island.outer.push_back({r * std::cos(t), r * std::sin(t)});
  }
  Ring lake;
  for (int i = 0; i < 30; ++i) {
    const double t = -2 * std::numbers::pi * i / 30;
    lake.push_back({2000 + 800 * std::cos(t), 1000 + 500 * std::sin(t)});
  }
  island.holes.push_back(lake);
  Polygon islet{{{16000, 0}, {17000, 0}, {17000, 1000}, {16000, 1000}}, {}};
  return {island, islet};
}

double bruteDistance(const MultiPolygon& land, Vec2 p) {
  double best = 1e300;
  auto ring = [&](const Ring& r) {
    for (std::size_t i = 0; i < r.size(); ++i)
      best = std::min(best, pointSegmentDistance(p, r[i], r[(i + 1) % r.size()]));
  };
  for (const Polygon& poly : land) {
    ring(poly.outer);
    for (const Ring& h : poly.holes)
      ring(h);
  }
  return best;
}

TEST(PolygonIndex, ContainsAgreesWithBruteForce) {
  const MultiPolygon land = wigglyLand();
  const PolygonIndex index(land);
  base::Rng rng(3);
  for (int i = 0; i < 20000; ++i) {
    const Vec2 p{rng.uniform(-15000, 18000), rng.uniform(-15000, 15000)};
    bool expected = false;
    for (const Polygon& poly : land)
      expected |= contains(poly, p);
    ASSERT_EQ(index.contains(p), expected) << p.x << "," << p.y;
  }
}

TEST(PolygonIndex, ClearanceIsALowerBoundOnEveryPointOfTheBox) {
  const MultiPolygon land = wigglyLand();
  const PolygonIndex index(land);
  base::Rng rng(5);
  int known = 0;
  for (int i = 0; i < 2000; ++i) {
    const Vec2 corner{rng.uniform(-15000, 18000), rng.uniform(-15000, 15000)};
    const Vec2 size{rng.uniform(10, 3000), rng.uniform(10, 3000)};
    const Aabb box{corner, corner + size};
    const PolygonIndex::Clearance clear = index.clearance(box);
    if (clear.distance <= 0.0)
      continue;
    ++known;
    for (int k = 0; k < 20; ++k) {
      const Vec2 p{rng.uniform(box.min.x, box.max.x), rng.uniform(box.min.y, box.max.y)};
      ASSERT_GE(bruteDistance(land, p), clear.distance) << p.x << "," << p.y;
      bool inside = false;
      for (const Polygon& poly : land)
        inside |= contains(poly, p);
      ASSERT_EQ(inside, clear.inside) << p.x << "," << p.y;
    }
  }
  EXPECT_GT(known, 200); // the bound is known for boxes clear of the coast, inside and out
}

TEST(PolygonIndex, NearestBoundaryAgreesWithBruteForce) {
  const MultiPolygon land = wigglyLand();
  const PolygonIndex index(land);
  base::Rng rng(4);
  for (int i = 0; i < 3000; ++i) {
    const Vec2 p{rng.uniform(-25000, 25000), rng.uniform(-25000, 25000)};
    const double expected = bruteDistance(land, p);
    const BoundaryHit hit = index.nearestBoundary(p, 1e9);
    ASSERT_NEAR(hit.distance, expected, 1e-6);
    ASSERT_NEAR(distance(hit.point, p), expected, 1e-6);
    // With a search limit, the answer is capped at the limit.
    const double capped = index.distanceToBoundary(p, 500.0);
    ASSERT_NEAR(capped, std::min(expected, 500.0), 1e-6);
  }
}

TEST(PolygonIndex, SegmentsMeetingABoxAgreeWithBruteForce) {
  const PolygonIndex index(wigglyLand());
  base::Rng rng(6);
  for (int i = 0; i < 500; ++i) {
    const Vec2 c{rng.uniform(-25000, 25000), rng.uniform(-25000, 25000)};
    const Aabb box = Aabb{c, c}.expanded(rng.uniform(0.0, 6000.0));
    std::vector<std::uint32_t> expected;
    for (std::uint32_t s = 0; s < index.segments().size(); ++s) {
      Aabb b;
      b.add(index.segments()[s].a);
      b.add(index.segments()[s].b);
      if (b.intersects(box))
        expected.push_back(s);
    }
    std::vector<std::uint32_t> got{7u}; // appended after what is there
    index.segmentsMeeting(box, got);
    ASSERT_EQ(got.front(), 7u);
    got.erase(got.begin());
    ASSERT_EQ(got, expected) << "box around " << c.x << ", " << c.y; // once each, ascending
  }
}

TEST(PolygonIndex, SegmentClearance) {
  const PolygonIndex index(wigglyLand());
  // A segment crossing the lake shore.
  EXPECT_TRUE(index.segmentNearBoundary({0, 1000}, {4000, 1000}, 0.0));
  // A short segment near the centre, far from every shore.
  EXPECT_FALSE(index.segmentNearBoundary({-3000, -3000}, {-2900, -3000}, 500.0));
  EXPECT_TRUE(index.segmentNearBoundary({-3000, -3000}, {-2900, -3000}, 1e5));
}

} // namespace
} // namespace strahler::geometry
