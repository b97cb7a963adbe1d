#include "engine_vegetation.h"

#include "lattice_density.h"
#include "parallel_chunks.h"

#include "strahler/geometry/projection.h"
#include "strahler/tiling/tile_scheme.h"
#include "strahler/tiling/water_mask.h"
#include "strahler/vegetation/web_tile.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace strahler::app {
namespace {

using base::ErrorCode;
using base::makeError;

/// One plant as a CSV line or a JSON object (with its leading comma when not the first); the
/// id in 16 hex digits, as the vegetation tiles write it.
std::string formatInstance(VegetationFormat format, Engine engine,
                           const vegetation::Instance& plant, const std::array<double, 3>& at,
                           bool first) {
  const double unit = engine == Engine::kUnreal ? 100.0 : 1.0;
  const char* species = vegetation::kSpecies[plant.species].name.data();
  char line[320];
  if (format == VegetationFormat::kCsv)
    std::snprintf(line, sizeof line, "%016llx,%s,%.3f,%.3f,%.3f,%.3f,%.4f,%.4f\n",
                  static_cast<unsigned long long>(plant.id), species, at[0], at[1], at[2],
                  plant.radius * unit, static_cast<double>(plant.scale),
                  static_cast<double>(plant.rotation));
  else
    std::snprintf(
        line, sizeof line,
        "%s\n  {\"id\": \"%016llx\", \"species\": \"%s\", \"position\": [%.3f, %.3f, %.3f], "
        "\"radius\": %.3f, \"scale\": %.4f, \"yaw\": %.4f}",
        first ? "" : ",", static_cast<unsigned long long>(plant.id), species, at[0], at[1], at[2],
        plant.radius * unit, static_cast<double>(plant.scale), static_cast<double>(plant.rotation));
  return line;
}

/// The Web Mercator tile (x, y) holding `lonLat` at kVegetationZoom.
std::pair<std::int64_t, std::int64_t> tileOf(geometry::Vec2 lonLat) {
  const geometry::Vec2 c = vegetation::tileCoordinates({kVegetationZoom, 0, 0}, lonLat);
  return {static_cast<std::int64_t>(std::floor(c.x)), static_cast<std::int64_t>(std::floor(c.y))};
}

} // namespace

base::Result<VegetationFormat> parseVegetationFormat(const std::string& name) {
  if (name == "csv")
    return VegetationFormat::kCsv;
  if (name == "json")
    return VegetationFormat::kJson;
  return makeError(ErrorCode::kInvalidInput, "--vegetation " + name + ": use csv or json");
}

double heightOnGrid(const VegetationGrid& g, geometry::Vec2 p) noexcept {
  const int n = g.size;
  const double column = std::clamp((p.x - g.box.min.x) / g.box.size().x * (n - 1), 0.0, n - 1.0);
  const double row = std::clamp((g.box.max.y - p.y) / g.box.size().y * (n - 1), 0.0, n - 1.0);
  const int c = std::min(static_cast<int>(column), n - 2),
            r = std::min(static_cast<int>(row), n - 2);
  const double tx = column - c, ty = row - r;
  const auto at = [&](int rr, int cc) {
    return static_cast<double>(g.heights[static_cast<std::size_t>(rr) * n + cc]);
  };
  return (1 - ty) * ((1 - tx) * at(r, c) + tx * at(r, c + 1)) +
         ty * ((1 - tx) * at(r + 1, c) + tx * at(r + 1, c + 1));
}

std::array<double, 3> engineCoordinates(Engine engine, const geometry::Aabb& box, geometry::Vec2 p,
                                        double z) noexcept {
  switch (engine) {
  case Engine::kUnity:
    return {p.x - box.min.x, z, p.y - box.min.y};
  case Engine::kUnreal:
    return {(p.x - box.min.x) * 100, (box.max.y - p.y) * 100, z * 100};
  case Engine::kGodot:
    return {p.x - box.min.x, z, box.max.y - p.y};
  default:
    return {p.x, p.y, z};
  }
}

base::Result<VegetationCount>
writeVegetation(const construction::World& world, const tiling::TileEvaluator& evaluator,
                Engine engine, VegetationFormat format, const VegetationGrid& g, int threads,
                std::ostream& out, std::atomic<long long>& tileRowsTotal,
                std::atomic<long long>& tileRowsDone, bool (*stop)()) {
  const geometry::LocalProjection projection(world.data().projectionCenter.x,
                                             world.data().projectionCenter.y);
  const tiling::TileScheme web = tiling::TileScheme::webMercator(projection);
  const tiling::WaterMask water(world, projection);
  const RenderContext context{evaluator, web};
  // The tiles whose footprints may hold a point of the box: its edges' tiles, one more around.
  std::int64_t x0 = INT64_MAX, y0 = INT64_MAX, x1 = INT64_MIN, y1 = INT64_MIN;
  for (int i = 0; i <= 16; ++i) {
    const double t = i / 16.0;
    for (const geometry::Vec2 p : {geometry::Vec2{g.box.min.x + t * g.box.size().x, g.box.min.y},
                                   geometry::Vec2{g.box.min.x + t * g.box.size().x, g.box.max.y},
                                   geometry::Vec2{g.box.min.x, g.box.min.y + t * g.box.size().y},
                                   geometry::Vec2{g.box.max.x, g.box.min.y + t * g.box.size().y}}) {
      const auto [x, y] = tileOf(projection.inverse(p));
      x0 = std::min(x0, x - 1), x1 = std::max(x1, x + 1);
      y0 = std::min(y0, y - 1), y1 = std::max(y1, y + 1);
    }
  }
  const std::int64_t last = (std::int64_t{1} << kVegetationZoom) - 1;
  x0 = std::max<std::int64_t>(x0, 0), y0 = std::max<std::int64_t>(y0, 0);
  x1 = std::min(x1, last), y1 = std::min(y1, last);
  tileRowsTotal.store(y1 - y0 + 1);
  if (format == VegetationFormat::kCsv)
    out << "id,species,x,y,z,radius,scale,yaw\n";
  else
    out << "{\"instances\": [";
  VegetationCount count;
  const int columns = static_cast<int>(x1 - x0 + 1);
  for (std::int64_t y = y0; y <= y1; ++y) {
    if (stop())
      return makeError(ErrorCode::kInternal, "interrupted");
    std::vector<std::vector<vegetation::Instance>> row(static_cast<std::size_t>(columns));
    std::vector<base::Status> status(static_cast<std::size_t>(columns), base::Ok{});
    forChunks(0, columns, 1, threads, [&](int i, int) {
      const geometry::TileId tile{kVegetationZoom, x0 + i, y};
      RenderedTile cost;
      const LatticeDensity density(context, world, water, tile, cost);
      auto placed = vegetation::placeWebTile(world.data().params.seed, projection, tile, density);
      if (!placed) {
        status[static_cast<std::size_t>(i)] = placed.error();
        return;
      }
      for (const vegetation::Instance& plant : placed.value())
        if (g.box.contains(plant.position))
          row[static_cast<std::size_t>(i)].push_back(plant);
    });
    for (int i = 0; i < columns; ++i) {
      STRAHLER_RETURN_IF_ERROR(status[static_cast<std::size_t>(i)]);
      for (const vegetation::Instance& plant : row[static_cast<std::size_t>(i)]) {
        const double z = heightOnGrid(g, plant.position);
        out << formatInstance(format, engine, plant,
                              engineCoordinates(engine, g.box, plant.position, z),
                              count.instances == 0);
        ++count.instances;
      }
    }
    count.tiles += columns;
    tileRowsDone.fetch_add(1);
  }
  if (format == VegetationFormat::kJson)
    out << "\n]}\n";
  if (!out)
    return makeError(ErrorCode::kIoError, "cannot write the vegetation instances");
  return count;
}

} // namespace strahler::app
