#include "world_commands.h"

#include "cli_args.h"
#include "command_support.h"
#include "layer_route.h"
#include "tile_service.h"
#include "world_summary.h"

#include "strahler/construction/world.h"
#include "strahler/geometry/tile_id.h"
#include "strahler/image/image.h"
#include "strahler/quality/analysis_report.h"
#include "strahler/quality/dem_file.h"
#include "strahler/quality/flow_field.h"
#include "strahler/quality/geomorphons.h"
#include "strahler/quality/hack_law.h"
#include "strahler/quality/network_coverage.h"
#include "strahler/quality/relief.h"
#include "strahler/quality/relief_windows.h"
#include "strahler/quality/river_agreement.h"
#include "strahler/quality/world_raster.h"
#include "strahler/render/relief_image.h"
#include "strahler/store/world_file.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <thread>
#include <variant>

namespace strahler::app {
namespace {

constexpr const char* kInfoUsage = "usage: strahler info WORLD.world\n"
                                   "Prints the statistics of a world file as JSON.\n";
constexpr const char* kRenderUsage =
    "usage: strahler render WORLD.world [--size PX] -o OUT.png\n"
    "Draws a shaded-relief overview of the whole world with its rivers (PX: 64..8192,\n"
    "default 1600, along the longer side).\n";
constexpr const char* kAnalyzeUsage =
    "usage: strahler analyze WORLD.world [--cell-size M] [--window-km KM] [--windows N]\n"
    "                        [--window-cell M] [--compare-dem FILE]\n"
    "       strahler analyze --dem FILE [--cell-size M] [--window-km KM] [--windows N]\n"
    "                        [--window-cell M]\n"
    "Checks that the terrain respects its water and prints JSON: the share of land cells\n"
    "(M metres, 5..1000, default 30) that drain to the sea or a lake after filling depressions\n"
    "shallower than 1 m (with rivers burnt in, and without), rises along river centrelines\n"
    "(tolerance 0.5 m), Horton's bifurcation and length ratios, and the relief figures of the\n"
    "terrain (slope-area concavity, slope percentiles, D8 confluences, drainage density,\n"
    "dissection, agreement of D8 channels with the rivers, sinuosity by Rosgen type,\n"
    "geomorphon class shares over the land: lookup 360 m, flatness 1 degree) and Hack's\n"
    "exponent h of the river graph (main-stream length L = c A^h against drainage area A).\n"
    "Window figures, as ../shared/realism/blind_set.py computes them: the N (default 3)\n"
    "highest-relief squares of KM km (default 7.5) wholly on land, at the raster's cell, each\n"
    "with its geomorphon shares (cells at least the lookup from its edge) and the spectral\n"
    "slope of its radially averaged power spectrum (wavelengths 4 cells to 2 km; larger means\n"
    "smoother), then their mean shares and median spectral slope. --window-cell M resamples\n"
    "the raster to M-metre cells for these (bilinearly, as the script's --cell does).\n"
    "--compare-dem FILE adds the same window figures of a DEM (read as --dem reads it; give\n"
    "--window-cell to compare at one cell), the geomorphon distance (half L1 of the mean\n"
    "shares) and the spectral slope difference.\n"
    "--dem: the relief figures of a real DEM instead: an ESRI ASCII grid (.asc; a grid in\n"
    "degrees gets square cells of its latitude spacing, its columns resampled as blind_set.py\n"
    "does; --cell-size replaces its cellsize instead) or any raster OpenImageIO reads\n"
    "(heights in metres; --cell-size M, metres > 0, required). NODATA cells count as outside.\n"
    "A world's raster may hold at most 60 million cells (up to about 7 GB); larger worlds need a\n"
    "larger --cell-size (e.g. 120 for 100,000 km²).\n";

constexpr const char* kTileUsage =
    "usage: strahler tile WORLD.world --scheme web|local|cesium --z Z --x X --y Y\n"
    "                     --format png|terrarium|png16|tif|exr|drc|glb|relief|terrain|mvt|json\n"
    "                     [--size N] -o FILE\n"
    "       strahler tile WORLD.world --scheme web|local --z Z --x X --y Y --layer NAME\n"
    "                     [--species tree|bush] [--azimuth DEG --altitude DEG] [--size N] -o FILE\n"
    "Writes one tile. web: Web Mercator XYZ (zoom 0..18); local: the world's metric\n"
    "quadtree; cesium: Cesium's geographic TMS pyramid (Y counts rows from the south),\n"
    "format terrain only: quantized-mesh-1.0 with normals, water mask and metadata.\n"
    "png is Terrain-RGB; relief an RGB picture (height tint x hillshade);\n"
    "mvt a Mapbox Vector Tile (web only: water, contours, rivers, features);\n"
    "json the trees and bushes of a tile (web only, zooms 16..18; docs/http.md).\n"
    "--layer: a derived layer as a grey PNG (slope, aspect, illumination, hillshade,\n"
    "humidity, sediment, vegetation, water; docs/http.md), instead of --format;\n"
    "--species for vegetation, --azimuth/--altitude for hillshade.\n"
    "N: pixels per side for rasters (16..1024, default 256),\n"
    "quads per side for meshes (4..256, default 64).\n";

/// The most raster cells `analyze` evaluates (55 bytes each at its peak on Mallorca at 30 m,
/// 113 on Iceland at 120 m).
constexpr double kMaxAnalysisCells = 60e6;

int threadCount() {
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

/// A world command's parsed options and its world file.
struct WorldCommand {
  CliArgs args;
  construction::WorldData world;
  std::size_t fileBytes = 0;
};

template <class T> base::Status statusOf(const base::Result<T>& result) {
  if (result)
    return base::Ok{};
  return result.error();
}

/// Checks a command's option values before its world file is read: a wrong command line is
/// found (exit 2) without reading any file.
using OptionCheck = std::function<base::Status(const CliArgs&)>;

/// Parses `WORLD` plus options (`required` ones must be there), runs `check`, then reads the
/// world file. Returns an exit code instead when any of them fails.
std::variant<WorldCommand, int> openWorld(const std::string& name,
                                          const std::vector<std::string>& raw,
                                          const std::set<std::string>& valued, const char* usage,
                                          const std::set<std::string>& required = {},
                                          const OptionCheck& check = {}) {
  auto parsed = CliArgs::parse(name, raw, valued, {"--help", "-h"});
  if (!parsed)
    return usageError(parsed.error(), name);
  if (parsed.value().has("--help") || parsed.value().has("-h"))
    return printUsage(usage);
  const std::vector<std::string>& positional = parsed.value().positional();
  if (positional.size() != 1)
    return usageError({base::ErrorCode::kInvalidInput,
                       positional.empty() ? "expected a WORLD file"
                                          : "expected one WORLD file, got " +
                                                std::to_string(positional.size()) + " arguments"},
                      name);
  for (const std::string& option : required)
    if (!parsed.value().get(option))
      return usageError({base::ErrorCode::kInvalidInput, "missing " + option}, name);
  if (check)
    if (auto checked = check(parsed.value()); !checked)
      return usageError(checked.error(), name);
  const std::string path = positional[0];
  auto world = readWorldArgument(path, generateFirstHint(path));
  if (!world)
    return fail(world.error());
  std::error_code ec;
  const auto bytes = std::filesystem::file_size(path, ec);
  return WorldCommand{std::move(parsed).value(), std::move(world).value(),
                      ec ? 0 : static_cast<std::size_t>(bytes)};
}

} // namespace

int runInfo(const std::vector<std::string>& raw) {
  auto opened = openWorld("info", raw, {}, kInfoUsage);
  if (auto* code = std::get_if<int>(&opened))
    return *code;
  const WorldCommand& c = std::get<WorldCommand>(opened);
  std::puts(toJson(summarize(c.world, c.fileBytes)).c_str());
  return 0;
}

int runRender(const std::vector<std::string>& raw) {
  const auto sizeOf = [](const CliArgs& args) { return args.getInt("--size", 64, 8192); };
  auto opened = openWorld("render", raw, {"--size", "-o"}, kRenderUsage, {"-o"},
                          [&](const CliArgs& args) { return statusOf(sizeOf(args)); });
  if (auto* code = std::get_if<int>(&opened))
    return *code;
  WorldCommand& c = std::get<WorldCommand>(opened);
  const auto size = sizeOf(c.args);
  const std::string out = c.args.get("-o").value_or("");
  const construction::World world(std::move(c.world));
  const auto image =
      render::drawReliefImage(world, static_cast<int>(size.value().value_or(1600)), threadCount());
  if (auto written = image::writePng(out, image); !written)
    return fail(written.error());
  return 0;
}

namespace {

/// The tile `tile`'s options ask for (everything but the world), or why they are wrong.
base::Result<TileRequest> tileRequestOf(const CliArgs& args) {
  const auto error = [](std::string message) {
    return base::makeError(base::ErrorCode::kInvalidInput, std::move(message));
  };
  const std::string scheme = args.get("--scheme").value_or("web");
  if (scheme != "web" && scheme != "local" && scheme != "cesium")
    return error("--scheme must be web, local or cesium");
  STRAHLER_ASSIGN_OR_RETURN(const auto z, args.getInt("--z", 0, 30));
  STRAHLER_ASSIGN_OR_RETURN(const auto x, args.getInt("--x", 0, (1ll << 30) - 1));
  STRAHLER_ASSIGN_OR_RETURN(const auto y, args.getInt("--y", 0, (1ll << 30) - 1));
  STRAHLER_ASSIGN_OR_RETURN(const auto size, args.getInt("--size", 1, 1 << 20));
  const auto layerName = args.get("--layer");
  if (layerName.has_value() == args.get("--format").has_value())
    return error("give --format or --layer (one of them)");
  TileRequest request;
  request.format = TileFormat::kLayerPng;
  if (!layerName) {
    for (const char* option : {"--species", "--azimuth", "--altitude"})
      if (args.get(option))
        return error(std::string(option) + " needs --layer");
    STRAHLER_ASSIGN_OR_RETURN(request.format, parseTileFormat(args.get("--format").value_or("")));
  } else {
    std::map<std::string, std::string> query;
    for (const char* option : {"species", "azimuth", "altitude"})
      if (auto value = args.get(std::string("--") + option))
        query[option] = *value;
    STRAHLER_ASSIGN_OR_RETURN(request.options.layer, parseLayerOptions(*layerName, query));
    if (scheme == "cesium")
      return error("--layer goes with --scheme web or local");
  }
  if (size) {
    const TileSizeRange range = tileSizeRange(tileKind(request.format));
    if (*size < range.min || *size > range.max)
      return error("option '--size' must be an integer in [" + std::to_string(range.min) + ", " +
                   std::to_string(range.max) + "] for " + canonicalFormatName(request.format) +
                   " tiles, got '" + std::to_string(*size) + "'");
  }
  if ((scheme == "cesium") != (request.format == TileFormat::kQuantizedMesh))
    return error("--format terrain goes with --scheme cesium, and only it");
  request.scheme = scheme == "local"    ? tiling::SchemeKind::kLocal
                   : scheme == "cesium" ? tiling::SchemeKind::kGeographic
                                        : tiling::SchemeKind::kWebMercator;
  request.tile = {static_cast<int>(z.value_or(0)), x.value_or(0), y.value_or(0)};
  if (request.scheme == tiling::SchemeKind::kGeographic) { // a TMS row, as in Cesium's URLs
    request.tile.y = geometry::flipRow(request.tile.z, request.tile.y);
    request.options.extensions = kOctVertexNormals | kWaterMask | kMetadata;
  }
  request.options.size = static_cast<int>(size.value_or(0));
  return request;
}

} // namespace

int runTile(const std::vector<std::string>& raw) {
  auto opened = openWorld("tile", raw,
                          {"--scheme", "--z", "--x", "--y", "--format", "--size", "-o", "--layer",
                           "--species", "--azimuth", "--altitude"},
                          kTileUsage, {"--z", "--x", "--y", "-o"},
                          [](const CliArgs& args) { return statusOf(tileRequestOf(args)); });
  if (auto* code = std::get_if<int>(&opened))
    return *code;
  WorldCommand& c = std::get<WorldCommand>(opened);
  const TileRequest request = tileRequestOf(c.args).value(); // checked by openWorld
  const TileService service(std::move(c.world));
  auto tile = service.render(request);
  if (!tile)
    return fail(tile.error());
  if (auto written = writeTextFile(c.args.get("-o").value_or(""), tile.value().bytes); !written)
    return fail(written.error());
  std::fprintf(stderr, "tile %s: %zu bytes, evaluate %.2f ms, encode %.2f ms, %zu blocks\n",
               c.args.get("-o").value_or("").c_str(), tile.value().bytes.size(),
               tile.value().evaluateMs, tile.value().encodeMs, tile.value().stats.blocks);
  return 0;
}

namespace {

/// Option `name`: a number in (0, `most`] of `unit`, or nothing when absent.
base::Result<std::optional<double>> positiveNumber(const CliArgs& args, const std::string& name,
                                                   double most, const std::string& unit) {
  const std::optional<std::string> text = args.get(name);
  if (!text)
    return std::optional<double>();
  double value = 0;
  const char* end = text->data() + text->size();
  const auto [ptr, ec] = std::from_chars(text->data(), end, value);
  if (ec != std::errc() || ptr != end || !std::isfinite(value) || value <= 0 || value > most) {
    char range[32];
    std::snprintf(range, sizeof range, "%g", most);
    return base::makeError(base::ErrorCode::kOutOfRange, name + " must be a number of " + unit +
                                                             " in (0, " + range + "], not '" +
                                                             *text + "'");
  }
  return std::optional<double>(value);
}

/// `--cell-size` of --dem mode: a positive number of metres, at most 100 km.
base::Result<std::optional<double>> demCellSize(const CliArgs& args) {
  return positiveNumber(args, "--cell-size", 1e5, "metres");
}

/// The window options: side in km and how many.
struct WindowOptions {
  double sizeKm = quality::kReliefWindowKm;
  int count = quality::kReliefWindowCount;
  std::optional<double> cellSize; ///< --window-cell: resample to this before taking windows.

  /// The window figures of `raster`, resampled first when a window cell is set.
  quality::ReliefWindows measure(const quality::HeightRaster& raster,
                                 const quality::GeomorphonParams& params) const {
    if (cellSize && std::abs(*cellSize - raster.cellSize) > 1e-6)
      return quality::measureReliefWindows(quality::resampleRaster(raster, *cellSize), sizeKm,
                                           count, params);
    return quality::measureReliefWindows(raster, sizeKm, count, params);
  }
};

base::Result<WindowOptions> windowOptions(const CliArgs& args) {
  WindowOptions options;
  STRAHLER_ASSIGN_OR_RETURN(const std::optional<double> km,
                            positiveNumber(args, "--window-km", 1000.0, "km"));
  STRAHLER_ASSIGN_OR_RETURN(const std::optional<long long> count, args.getInt("--windows", 0, 100));
  STRAHLER_ASSIGN_OR_RETURN(options.cellSize, positiveNumber(args, "--window-cell", 1e5, "metres"));
  options.sizeKm = km.value_or(options.sizeKm);
  options.count = static_cast<int>(count.value_or(options.count));
  return options;
}

/// The relief figures of `raster`, and those against the world's rivers when there is a world.
quality::ReliefReport reliefReport(const quality::HeightRaster& raster,
                                   const construction::World* world, const WindowOptions& windows) {
  quality::ReliefReport report;
  report.width = raster.width;
  report.height = raster.height;
  report.cellSize = raster.cellSize;
  const quality::FlowField flow = quality::computeFlowField(raster);
  report.terrain = quality::measureRelief(raster, flow);
  report.geomorphons = quality::geomorphonShares(raster, report.geomorphonParams);
  report.windowKm = windows.sizeKm;
  report.windows = windows.measure(raster, report.geomorphonParams);
  if (world != nullptr) {
    report.network = quality::compareWithRivers(*world, raster, flow);
    report.drainingFractionUnburnt = quality::checkDrainage(raster, 1.0).drainingFraction;
  }
  return report;
}

int analyzeDem(const CliArgs& args) {
  if (!args.positional().empty())
    return usageError({base::ErrorCode::kInvalidInput, "--dem takes no WORLD file"}, "analyze");
  auto cellSize = demCellSize(args);
  if (!cellSize)
    return usageError(cellSize.error(), "analyze");
  auto windows = windowOptions(args);
  if (!windows)
    return usageError(windows.error(), "analyze");
  const std::string path = args.get("--dem").value_or("");
  auto raster = quality::readDemFile(path, cellSize.value());
  if (!raster)
    return fail(raster.error());
  std::puts(
      quality::demReportJson(path, reliefReport(raster.value(), nullptr, windows.value())).c_str());
  return 0;
}

} // namespace

int runAnalyze(const std::vector<std::string>& raw) {
  auto parsed = CliArgs::parse(
      "analyze", raw,
      {"--cell-size", "--dem", "--window-km", "--windows", "--window-cell", "--compare-dem"},
      {"--help", "-h"});
  if (!parsed)
    return usageError(parsed.error(), "analyze");
  if (parsed.value().has("--help") || parsed.value().has("-h"))
    return printUsage(kAnalyzeUsage);
  if (parsed.value().get("--dem") && parsed.value().get("--compare-dem"))
    return usageError({base::ErrorCode::kInvalidInput, "--compare-dem needs a WORLD, not --dem"},
                      "analyze");
  if (parsed.value().get("--dem"))
    return analyzeDem(parsed.value());
  auto opened = openWorld(
      "analyze", raw, {"--cell-size", "--window-km", "--windows", "--window-cell", "--compare-dem"},
      kAnalyzeUsage, {}, [](const CliArgs& args) -> base::Status {
        STRAHLER_RETURN_IF_ERROR(args.getInt("--cell-size", 5, 1000));
        return statusOf(windowOptions(args));
      });
  if (auto* code = std::get_if<int>(&opened))
    return *code;
  WorldCommand& c = std::get<WorldCommand>(opened);
  auto cell = c.args.getInt("--cell-size", 5, 1000);
  if (!cell)
    return usageError(cell.error(), "analyze");
  auto windows = windowOptions(c.args);
  if (!windows)
    return usageError(windows.error(), "analyze");
  std::optional<quality::HeightRaster> reference;
  if (const auto dem = c.args.get("--compare-dem")) {
    auto read = quality::readDemFile(*dem, std::nullopt);
    if (!read)
      return fail(read.error());
    reference = std::move(read).value();
  }
  const construction::World world(std::move(c.world));
  const double cellSize = static_cast<double>(cell.value().value_or(30));
  if (const double cells = quality::worldRasterCells(world, cellSize); cells > kMaxAnalysisCells)
    return fail(base::makeError(
        base::ErrorCode::kLimitExceeded,
        "this world at " + std::to_string(cell.value().value_or(30)) +
            " m cells needs a raster of " + std::to_string(std::llround(cells / 1e6)) +
            " million cells, more than the 60 million analyze holds: use a " +
            "larger --cell-size (at least " +
            std::to_string(static_cast<long long>(
                std::ceil(cellSize * std::sqrt(cells / kMaxAnalysisCells)))) +
            ")"));
  quality::HeightRaster raster =
      quality::rasterizeWorld(world, cellSize, threadCount(), quality::RiverBurning::kNone);
  quality::ReliefReport relief = reliefReport(raster, &world, windows.value());
  if (reference)
    relief.comparison = quality::compareReliefWindows(
        relief.windows, c.args.get("--compare-dem").value_or(""), reference->cellSize,
        windows.value().measure(*reference, relief.geomorphonParams));
  quality::burnRivers(world, raster);
  const quality::DrainageReport drainage = quality::checkDrainage(raster, 1.0);
  const quality::RiverProfileReport rivers = quality::checkRiversDescend(
      quality::riverCentrelines(world), [&](geometry::Vec2 p) { return world.height(p, 1.0); }, 5.0,
      0.5);
  const quality::HortonStatistics horton = quality::hortonStatistics(world.data().network);
  const quality::HackLaw hack =
      quality::fitHackLaw(world.data().network, quality::networkDrainageAreasKm2(world));
  const quality::NetworkCoverage coverage =
      quality::networkCoverage(world.data().network, world.land());
  std::puts(quality::analysisReportJson(drainage, horton, rivers, relief, hack, coverage).c_str());
  return 0;
}

} // namespace strahler::app
