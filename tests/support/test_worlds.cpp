#include "test_worlds.h"

#include "strahler/base/assert.h"
#include "strahler/input/coastline.h"

#include <fstream>
#include <sstream>

namespace strahler::test_support {
namespace {

input::WorldSpec specFrom(const std::string& name, std::string_view geojson, std::uint64_t seed) {
  input::Params params;
  params.seed = seed;
  auto spec = input::makeWorldSpec(name, geojson, params);
  STRAHLER_ASSERT(spec.ok(), "test world must load");
  return std::move(spec).value();
}

} // namespace

std::string readTestData(const std::string& name) {
  std::ifstream in(std::string(STRAHLER_TEST_DATA_DIR) + "/" + name, std::ios::binary);
  STRAHLER_ASSERT(static_cast<bool>(in), "test data file must exist");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

input::WorldSpec defaultIslandSpec(std::uint64_t seed) {
  return specFrom("default", input::defaultCoastlineGeoJson(), seed);
}

input::WorldSpec mallorcaSpec(std::uint64_t seed) {
  return specFrom("mallorca", readTestData("mallorca.geojson"), seed);
}

input::WorldSpec scaledMallorcaSpec(double scale, std::uint64_t seed) {
  input::WorldSpec spec = mallorcaSpec(seed);
  for (geometry::Polygon& p : spec.land) {
    for (geometry::Vec2& v : p.outer)
      v = v * scale;
    for (geometry::Ring& h : p.holes)
      for (geometry::Vec2& v : h)
        v = v * scale;
  }
  return spec;
}

input::WorldSpec corsicaSpec(std::uint64_t seed) {
  return specFrom("corsica", readTestData("corsica.geojson"), seed);
}

} // namespace strahler::test_support
