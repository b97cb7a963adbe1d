// Writes real tiles of the default island through the tile service, with the heights the
// whole-world evaluator (World::height) gives at the same samples, so that the independent
// decoders in tests/node check our bytes against the terrain itself:
//   <dir>/heightmaps/<name>.<format>.png + .json   (check_heightmaps.mjs)
//   <dir>/meshes/<name>.drc, .glb + .json          (check_draco.mjs, validate_glb.mjs)
//   <dir>/relief/<name>.png + .rgb + .json         (check_relief.mjs: colour relief, the .rgb
//                                                   pixels shaded from World::height)
//   <dir>/vector/<name>.mvt + .json                (check_mvt.mjs: the tile, and the world's
//                                                   river lines in degrees; or, for the
//                                                   encoder's sample, the exact content)
//   <dir>/layers/<name>.<layer>.png + .json        (check_layers.mjs: layer tiles, the .json
//                                                   values computed from World::height)
#include "mesh_renderer.h"
#include "test_worlds.h"
#include "tile_service.h"
#include "vector_layers.h"

#include "strahler/construction/world_builder.h"
#include "strahler/encoding/mesh.h"
#include "strahler/layers/sediment.h"
#include "strahler/layers/sky_view.h"
#include "strahler/layers/slope.h"
#include "strahler/render/river_sections.h"
#include "strahler/render/shaded_relief.h"
#include "strahler/vector_tile/vector_tile.h"

#include <charconv>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace {

namespace fs = std::filesystem;
using namespace strahler;

std::string number(double v) {
  char text[32];
  return std::string(text, std::to_chars(text, text + sizeof text, v).ptr);
}

template <class T> std::string array(const std::vector<T>& values) {
  std::string out = "[";
  for (std::size_t i = 0; i < values.size(); ++i)
    out += (i ? "," : "") + number(static_cast<double>(values[i]));
  return out + "]";
}

bool write(const fs::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  return static_cast<bool>(out);
}

/// Heights of a sample grid from the whole-world evaluator.
std::vector<double> reference(const construction::World& world, const tiling::SampleGrid& grid) {
  std::vector<double> h;
  for (std::size_t k = 0; k < grid.points.size(); ++k)
    h.push_back(
        world.height(grid.points[k], grid.rowSpacing[k / static_cast<std::size_t>(grid.width)]));
  return h;
}

bool heightmaps(const app::TileService& service, const fs::path& dir, const geometry::TileId& tile,
                const std::string& name) {
  const tiling::SampleGrid grid =
      service.scheme(tiling::SchemeKind::kWebMercator).rasterGrid(tile, 64);
  std::vector<double> h = reference(service.world(), grid);
  const std::pair<app::TileFormat, const char*> formats[] = {
      {app::TileFormat::kTerrainRgb, "terrainrgb"},
      {app::TileFormat::kTerrarium, "terrarium"},
      {app::TileFormat::kPng16, "png16"}};
  for (const auto& [format, label] : formats) {
    auto rendered = service.render({tiling::SchemeKind::kWebMercator, tile, format, {64}, {}});
    if (!rendered)
      return false;
    // The tile stores float32 heights; the reference is the same value before that rounding.
    std::vector<float> asFloat(h.begin(), h.end());
    const std::string json = "{\"format\":\"" + std::string(label) +
                             "\",\"width\":64,\"height\":64,\"heights\":" + array(asFloat) + "}\n";
    const fs::path stem = dir / (name + "." + label);
    if (!write(stem.string() + ".png", rendered.value().bytes) ||
        !write(stem.string() + ".json", json))
      return false;
  }
  return true;
}

bool meshes(const app::TileService& service, const fs::path& dir, const geometry::TileId& tile,
            const std::string& name) {
  const int quads = 32;
  const tiling::TileScheme& scheme = service.scheme(tiling::SchemeKind::kLocal);
  const tiling::SampleGrid grid = scheme.meshGrid(tile, quads);
  encoding::MeshGridInput input;
  input.quads = quads;
  std::tie(input.origin, input.spacing) = scheme.meshFrame(tile, quads);
  const std::vector<double> h = reference(service.world(), grid);
  input.heights.assign(h.begin(), h.end());
  input.skirtDepth = std::max(1.0, 0.5 * input.spacing);
  auto mesh = encoding::buildGridMesh(input);
  auto drc =
      service.render({tiling::SchemeKind::kLocal, tile, app::TileFormat::kDraco, {quads}, {}});
  auto glb = service.render({tiling::SchemeKind::kLocal, tile, app::TileFormat::kGlb, {quads}, {}});
  if (!mesh || !drc || !glb)
    return false;
  const std::string json =
      "{\"name\":\"" + name + "\",\"drc\":\"" + name + ".drc\",\"glb\":\"" + name +
      ".glb\",\"maxPositionError\":" + number(app::meshPositionError(input.spacing)) +
      ",\"spacing\":" + number(input.spacing) + ",\"hasUv\":true,\"origin\":[" +
      number(input.origin.x) + "," + number(input.origin.y) +
      "],\"positions\":" + array(mesh.value().positions) +
      ",\"indices\":" + array(mesh.value().indices) + "}\n";
  return write(dir / (name + ".drc"), drc.value().bytes) &&
         write(dir / (name + ".glb"), glb.value().bytes) && write(dir / (name + ".json"), json);
}

/// A colour-relief tile and the pixels render::shadeRelief makes of the whole-world
/// evaluator's heights at its bordered samples; `east` names its east neighbour's sample, if
/// written, for the seam check.
bool relief(const app::TileService& service, const fs::path& dir, tiling::SchemeKind scheme,
            const geometry::TileId& tile, int size, const std::string& name,
            const std::string& east = "") {
  const tiling::SampleGrid grid = service.scheme(scheme).borderedRasterGrid(tile, size);
  const image::RgbImage expected =
      render::shadeRelief(reference(service.world(), grid), size, size, grid.rowSpacing);
  auto rendered = service.render({scheme, tile, app::TileFormat::kRelief, {size}, {}});
  if (!rendered)
    return false;
  const std::string json = "{\"width\":" + std::to_string(size) +
                           ",\"height\":" + std::to_string(size) + ",\"east\":\"" + east + "\"}\n";
  return write(dir / (name + ".png"), rendered.value().bytes) &&
         write(dir / (name + ".rgb"),
               std::string(expected.pixels.begin(), expected.pixels.end())) &&
         write(dir / (name + ".json"), json);
}

/// A vector tile and the world's river sections of the orders it shows, in degrees, at full
/// resolution (render::forEachRiverSection's lines), for check_mvt.mjs to place the tile's
/// rivers by its own Web Mercator.
bool vector(const app::TileService& service, const fs::path& dir, const geometry::TileId& tile,
            const std::string& name) {
  auto rendered =
      service.render({tiling::SchemeKind::kWebMercator, tile, app::TileFormat::kMvt, {}, {}});
  if (!rendered)
    return false;
  const construction::WorldData& world = service.world().data();
  const geometry::LocalProjection projection(world.projectionCenter.x, world.projectionCenter.y);
  int maxOrder = 1;
  render::forEachRiverSection(
      world, [&](const render::RiverSection& s) { maxOrder = std::max(maxOrder, s.strahler); });
  const int minOrder = app::minRiverOrder(tile.z, maxOrder);
  std::string rivers;
  render::forEachRiverSection(world, [&](const render::RiverSection& s) {
    if (s.strahler < minOrder)
      return;
    rivers += rivers.empty() ? "[[" : ",[";
    for (std::size_t k = 0; k < s.line.size(); ++k) {
      const geometry::Vec2 ll = projection.inverse(s.line[k]);
      rivers += (k ? ",[" : "[") + number(ll.x) + "," + number(ll.y) + "]";
    }
    rivers += "]";
  });
  const std::string json = "{\"z\":" + std::to_string(tile.z) + ",\"x\":" + std::to_string(tile.x) +
                           ",\"y\":" + std::to_string(tile.y) +
                           ",\"buffer\":" + std::to_string(app::kVectorBuffer) +
                           ",\"features\":" + (world.features.empty() ? "false" : "true") +
                           ",\"rivers\":" + (rivers.empty() ? "[]" : rivers + "]") + "}\n";
  return write(dir / (name + ".mvt"), rendered.value().bytes) &&
         write(dir / (name + ".json"), json);
}

/// A tile made by the MVT encoder directly, with every geometry type (a multipoint, two lines,
/// a polygon with a hole), negative and buffer coordinates and every value type, and its
/// content as JSON for check_mvt.mjs to compare with what @mapbox/vector-tile decodes.
bool encoderSample(const fs::path& dir) {
  using vector_tile::GeometryType;
  const vector_tile::Tile tile{{
      {"points",
       4096,
       {{GeometryType::kPoint, {{{1, 2}}, {{-30, 4100}}}, {{"name", std::string("Río")}}, 9}}},
      {"lines",
       4096,
       {{GeometryType::kLineString,
         {{{0, 0}, {4096, 4096}}, {{-64, 10}, {10, -64}, {4160, 4160}}},
         {{"order", std::int64_t{-3}}, {"flow", 12.25}, {"index", true}},
         0}}},
      {"polygons",
       4096,
       {{GeometryType::kPolygon,
         {{{0, 0}, {100, 0}, {100, 100}, {0, 100}}, {{10, 10}, {10, 90}, {90, 90}, {90, 10}}},
         {{"kind", std::string("lake")}, {"big", false}},
         0}}},
  }};
  const std::string json =
      R"({"exact":{"points":[{"type":1,"id":9,"properties":{"name":"Río"},)"
      R"("geometry":[[[1,2]],[[-30,4100]]]}],)"
      R"("lines":[{"type":2,"properties":{"order":-3,"flow":12.25,"index":true},)"
      R"("geometry":[[[0,0],[4096,4096]],[[-64,10],[10,-64],[4160,4160]]]}],)"
      R"("polygons":[{"type":3,"properties":{"kind":"lake","big":false},)"
      R"("geometry":[[[0,0],[100,0],[100,100],[0,100],[0,0]],)"
      R"([[10,10],[10,90],[90,90],[90,10],[10,10]]]}]}})"
      "\n";
  return write(dir / "encoder.mvt", vector_tile::encodeTile(tile)) &&
         write(dir / "encoder.json", json);
}

/// Layer tiles (slope, illumination, sediment, hillshade) and the values core/layers computes
/// from the whole-world evaluator's heights at the same bordered samples, as the tile encodes
/// them; `east` names the tile's east neighbour's sample, if written, for the seam check.
bool layerTiles(const app::TileService& service, const fs::path& dir, tiling::SchemeKind scheme,
                const geometry::TileId& tile, int size, const std::string& name,
                const std::string& east = "") {
  const int border = layers::SkyView::kReach + 1; // the renderer's, for the sky view of even tiles
  const tiling::SampleGrid grid = service.scheme(scheme).borderedRasterGrid(tile, size, border);
  const std::vector<double> heights = reference(service.world(), grid);
  const layers::BorderedHeights h{heights, size, size, border, grid.rowSpacing};
  std::vector<double> shade;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const layers::Gradient g = layers::gradientAt(h, x, y);
      shade.push_back(255.0 * render::sunIllumination(g.dzdx, g.dzdy, {}));
    }
  auto scaled = [](std::vector<double> v, double scale) {
    for (double& x : v)
      x *= scale;
    return v;
  };
  const struct {
    app::LayerName layer;
    const char* label;
    int depth;
    std::vector<double> expected;
  } samples[] = {
      {app::LayerName::kSlope, "slope", 16, scaled(layers::slopeDegrees(h), 100.0)},
      {app::LayerName::kIllumination, "illumination", 8,
       scaled(layers::skyView(h, size % 2 == 0 ? 2 : 1), 255.0)},
      {app::LayerName::kSediment, "sediment", 8, scaled(layers::sedimentThickness(h), 100.0)},
      {app::LayerName::kHillshade, "hillshade", 8, shade},
  };
  for (const auto& sample : samples) {
    app::TileRequest request{scheme, tile, app::TileFormat::kLayerPng, {size}, {}};
    request.options.layer.name = sample.layer;
    if (sample.layer == app::LayerName::kHillshade) {
      request.options.layer.azimuthDeg = 315.0;
      request.options.layer.altitudeDeg = 45.0;
    }
    auto rendered = service.render(request);
    if (!rendered)
      return false;
    const std::string file = name + "." + sample.label;
    // Slope and hillshade also get the bordered heights, from which check_layers.mjs computes
    // them itself (not through core/layers).
    const bool own =
        sample.layer == app::LayerName::kSlope || sample.layer == app::LayerName::kHillshade;
    const std::string input = own ? ",\"border\":" + std::to_string(border) +
                                        ",\"rowSpacing\":" + array(grid.rowSpacing) +
                                        ",\"heights\":" + array(heights)
                                  : "";
    const std::string json = "{\"width\":" + std::to_string(size) +
                             ",\"height\":" + std::to_string(size) +
                             ",\"depth\":" + std::to_string(sample.depth) + ",\"east\":\"" +
                             (east.empty() ? "" : east + "." + sample.label) +
                             "\",\"expected\":" + array(sample.expected) + input + "}\n";
    if (!write(dir / (file + ".png"), rendered.value().bytes) ||
        !write(dir / (file + ".json"), json))
      return false;
  }
  return true;
}

} // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: write_world_tile_samples DIR\n");
    return 2;
  }
  const fs::path dir = argv[1];
  fs::remove_all(dir);
  fs::create_directories(dir / "heightmaps");
  fs::create_directories(dir / "meshes");
  fs::create_directories(dir / "relief");
  fs::create_directories(dir / "vector");
  fs::create_directories(dir / "layers");
  const app::TileService service(
      construction::generateWorldData(test_support::defaultIslandSpec(), "samples").value());
  // Web tiles over the island's centre at a coarse and a fine zoom; local tiles inland and at the
  // coast.
  const bool ok =
      heightmaps(service, dir / "heightmaps", {10, 434, 373}, "island-z10") &&
      heightmaps(service, dir / "heightmaps", {13, 3477, 2990}, "island-z13") &&
      meshes(service, dir / "meshes", {4, 7, 8}, "local-z4-7-8") &&
      meshes(service, dir / "meshes", {3, 0, 3}, "local-z3-0-3") &&
      relief(service, dir / "relief", tiling::SchemeKind::kWebMercator, {12, 1736, 1494}, 256,
             "island-z12-1736", "island-z12-1737") &&
      relief(service, dir / "relief", tiling::SchemeKind::kWebMercator, {12, 1737, 1494}, 256,
             "island-z12-1737") &&
      relief(service, dir / "relief", tiling::SchemeKind::kLocal, {2, 1, 2}, 64, "local-z2-1-2") &&
      vector(service, dir / "vector", {10, 434, 373}, "island-z10") &&
      vector(service, dir / "vector", {12, 1736, 1494}, "island-z12") &&
      encoderSample(dir / "vector") &&
      layerTiles(service, dir / "layers", tiling::SchemeKind::kWebMercator, {12, 1736, 1494}, 128,
                 "island-z12-1736", "island-z12-1737") &&
      layerTiles(service, dir / "layers", tiling::SchemeKind::kWebMercator, {12, 1737, 1494}, 128,
                 "island-z12-1737") &&
      layerTiles(service, dir / "layers", tiling::SchemeKind::kLocal, {2, 1, 2}, 64,
                 "local-z2-1-2");
  if (!ok) {
    std::fprintf(stderr, "write_world_tile_samples: could not render or write a tile\n");
    return 1;
  }
  std::printf("wrote real tiles to %s\n", dir.c_str());
  return 0;
}
