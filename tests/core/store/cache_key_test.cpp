// Cache keys: a function of what determines the world, and of nothing else.

#include "result_matchers.h"

#include "strahler/store/cache_key.h"

#include <gtest/gtest.h>

#include <charconv>
#include <string>

namespace strahler::store {
namespace {

std::string shortest(double v) {
  char buffer[32];
  return {buffer, std::to_chars(buffer, buffer + sizeof buffer, v).ptr};
}

/// A GeoJSON island (with a lake) whose first vertex is (west, 42.0).
std::string islandGeoJson(double west = 8.5) {
  return R"({"type":"Polygon","coordinates":[[[)" + shortest(west) +
         R"(,42.0],[8.62,42.0],[8.62,42.1],[8.5,42.1],[)" + shortest(west) +
         R"(,42.0]],[[8.55,42.04],[8.55,42.06],[8.57,42.06],[8.57,42.04],[8.55,42.04]]]})";
}

input::WorldSpec makeSpec(const std::string& name = "island", const input::Params& params = {},
                          const std::string& geoJson = islandGeoJson()) {
  auto spec = input::makeWorldSpec(name, geoJson, params);
  return test_support::valueOf(std::move(spec));
}

constexpr std::string_view kVersion = "0.1.0";

TEST(CacheKey, IsThirtyTwoHexDigitsAndValid) {
  const std::string key = cacheKey(makeSpec(), kVersion);
  EXPECT_EQ(key.size(), 32u);
  EXPECT_EQ(key.find_first_not_of("0123456789abcdef"), std::string::npos) << key;
  EXPECT_TRUE(isValidCacheKey(key));
}

TEST(CacheKey, SameSpecGivesTheSameKey) {
  EXPECT_EQ(cacheKey(makeSpec(), kVersion), cacheKey(makeSpec(), kVersion));
}

TEST(CacheKey, NameIsNotPartOfTheKey) {
  EXPECT_EQ(cacheKey(makeSpec("island"), kVersion), cacheKey(makeSpec("copy-of-island"), kVersion));
}

TEST(CacheKey, SeedParamsCoastlineAndVersionChangeTheKey) {
  const std::string base = cacheKey(makeSpec(), kVersion);
  input::Params seeded;
  seeded.seed = 2;
  EXPECT_NE(cacheKey(makeSpec("island", seeded), kVersion), base);
  input::Params longer;
  longer.edgeLength = 1001.0;
  EXPECT_NE(cacheKey(makeSpec("island", longer), kVersion), base);
  EXPECT_NE(cacheKey(makeSpec("island", {}, islandGeoJson(8.5000001)), kVersion), base);
  EXPECT_NE(cacheKey(makeSpec(), "0.1.1"), base);
}

/// GeoJSON of a coastline, every number written so that it reads back exactly.
std::string multiPolygonGeoJson(const geometry::MultiPolygon& land) {
  auto ring = [](const geometry::Ring& r) {
    std::string out = "[";
    for (std::size_t i = 0; i <= r.size(); ++i) {
      const geometry::Vec2 v = r[i % r.size()];
      out += (i ? ",[" : "[") + shortest(v.x) + "," + shortest(v.y) + "]";
    }
    return out + "]";
  };
  std::string out = R"({"type":"MultiPolygon","coordinates":[)";
  for (std::size_t p = 0; p < land.size(); ++p) {
    out += (p ? ",[" : "[") + ring(land[p].outer);
    for (const geometry::Ring& hole : land[p].holes)
      out += "," + ring(hole);
    out += "]";
  }
  return out + "]}";
}

TEST(CacheKey, RepairedCoastIsKeyedByItsGeometryAlone) {
  // A bow tie: --repair keeps both lobes and joins them where they cross.
  const std::string bowtie =
      R"({"type":"Polygon","coordinates":[[[8.5,42],[8.6,42.1],[8.6,42],[8.5,42.1],[8.5,42]]]})";
  const std::string other =
      R"({"type":"Polygon","coordinates":[[[8.5,42],[8.6,42.1],[8.6,42],[8.5,42.11],[8.5,42]]]})";
  auto repaired = input::makeWorldSpec("bowtie", bowtie, {}, {}, true);
  auto repairedOther = input::makeWorldSpec("other", other, {}, {}, true);
  STRAHLER_ASSERT_OK(repaired);
  STRAHLER_ASSERT_OK(repairedOther);
  ASSERT_FALSE(repaired.value().repairs.empty());
  const std::string key = cacheKey(repaired.value(), kVersion);
  EXPECT_NE(cacheKey(repairedOther.value(), kVersion), key);
  // The same geometry given as a valid coastline (no repair needed) shares the key: the key
  // follows the land, not how it was obtained.
  STRAHLER_ASSIGN_OR_ASSERT(
      auto same,
      input::makeWorldSpec("same", multiPolygonGeoJson(repaired.value().landLonLat), {}));
  EXPECT_EQ(cacheKey(same, kVersion), key);
}

TEST(CacheKey, UserMouthsChangeTheKey) {
  input::WorldSpec spec = makeSpec();
  const std::string base = cacheKey(spec, kVersion);
  spec.mouths.push_back({{8.5, 42.05}, {0.0, 0.0}, 3});
  const std::string withMouth = cacheKey(spec, kVersion);
  EXPECT_NE(withMouth, base);
  spec.mouths.back().priority = 4;
  EXPECT_NE(cacheKey(spec, kVersion), withMouth);
}

TEST(CacheKey, ConstraintPixelsChangeTheKey) {
  input::WorldSpec spec = makeSpec();
  input::ConstraintMap map;
  map.bounds = {8.5, 42.0, 8.62, 42.1};
  map.image = {2, 2, {0.0f, 0.25f, 0.5f, 1.0f}};
  spec.constraints.push_back(map);
  const std::string before = cacheKey(spec, kVersion);
  spec.constraints[0].image.pixels[3] = 0.999f;
  const std::string pixel = cacheKey(spec, kVersion);
  spec.constraints[0].kind = input::ConstraintKind::kRiverSlope;
  const std::string kind = cacheKey(spec, kVersion);
  spec.constraints[0].bounds.north = 42.2;
  const std::string bounds = cacheKey(spec, kVersion);
  EXPECT_NE(before, cacheKey(makeSpec(), kVersion));
  EXPECT_NE(pixel, before);
  EXPECT_NE(kind, pixel);
  EXPECT_NE(bounds, kind);
}

TEST(CacheKey, CanonicalTextUsesShortestRoundTripNumbers) {
  const std::string text = canonicalSpecText(makeSpec(), kVersion);
  EXPECT_NE(text.find("\n8.62 42.1\n"), std::string::npos) << text;
  EXPECT_NE(text.find("generator 5:0.1.0\n"), std::string::npos) << text;
  EXPECT_EQ(text.find("island"), std::string::npos) << "the name must not be hashed";
}

TEST(CacheKey, ValidKeys) {
  EXPECT_TRUE(isValidCacheKey("abc-DEF_123"));
  EXPECT_FALSE(isValidCacheKey(""));
  EXPECT_FALSE(isValidCacheKey("a.b"));
  EXPECT_FALSE(isValidCacheKey("../x"));
  EXPECT_FALSE(isValidCacheKey(std::string(129, 'a')));
}

} // namespace
} // namespace strahler::store
