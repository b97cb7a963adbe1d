#include "export_command.h"

#include "atomic_output.h"
#include "cli_args.h"
#include "command_support.h"
#include "export_plan.h"
#include "hilbert_tile_id.h"
#include "layer_route.h"
#include "mbtiles_writer.h"
#include "ordered_renderer.h"
#include "pmtiles_writer.h"
#include "terminal_progress.h"
#include "tile_service.h"
#include "vector_layers.h"
#include "world_version.h"

#include "strahler/store/world_file.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <fcntl.h>
#include <filesystem>
#include <map>
#include <optional>
#include <thread>
#include <unistd.h>

namespace strahler::app {
namespace {

using base::ErrorCode;
using base::makeError;
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr const char* kExportUsage =
    "usage: strahler export WORLD.world --zooms A-B -o FILE.pmtiles|FILE.mbtiles\n"
    "                       [--format pmtiles|mbtiles] [--scheme web] [--bbox W,S,E,N]\n"
    "                       [--tile png|terrarium|png16|relief|mvt] [--size N] [--threads N]\n"
    "                       [--max-tiles N] [--quiet]\n"
    "       strahler export WORLD.world --zooms A-B -o FILE --layer NAME [--species tree|bush]\n"
    "                       [--azimuth DEG --altitude DEG] [options above but --tile]\n"
    "Writes every Web Mercator tile of the world in zooms A..B (0..18) that touches its bounds\n"
    "(and --bbox, degrees) to a PMTiles v3 or MBTiles 1.3 archive, byte for byte the tiles\n"
    "`strahler serve` sends. --format defaults to the extension of FILE. png is Terrain-RGB\n"
    "(the default), relief a colour-relief picture, mvt the vector tiles (gzipped; no --size);\n"
    "N: pixels per side, 16..1024, default 256. --threads: default all cores; the archive is\n"
    "the same for any count. Identical tiles (the open sea) are stored once.\n"
    "--layer: a derived layer's grey PNG tiles instead (slope, aspect, illumination, hillshade,\n"
    "humidity, sediment, vegetation, water), as\n"
    "`strahler tile --layer` and the layers/ URLs give them; --species for vegetation,\n"
    "--azimuth/--altitude for hillshade.\n"
    "More than --max-tiles tiles (default 5000000) are refused. The archive is written to\n"
    "FILE.tmp.PID and renamed when complete; on an error or SIGINT/SIGTERM nothing is left.\n";

constexpr std::uint64_t kDefaultMaxTiles = 5'000'000;

enum class ArchiveKind { kPmtiles, kMbtiles };

/// What the command line asked for.
struct ExportOptions {
  ArchiveKind kind = ArchiveKind::kPmtiles;
  TileFormat tile = TileFormat::kTerrainRgb;
  int size = TileSizes::kRasterDefault;
  int threads = 1;
  std::uint64_t maxTiles = kDefaultMaxTiles;
  std::pair<int, int> zooms;
  std::optional<LonLatBox> bbox;
  std::optional<LayerOptions> layer; ///< --layer: tile is TileFormat::kLayerPng.
  std::string output;
  bool quiet = false;
};

base::Result<ArchiveKind> archiveKind(const CliArgs& args, const std::string& output) {
  std::string name = args.get("--format").value_or("");
  if (name.empty()) {
    if (endsWith(output, ".pmtiles"))
      return ArchiveKind::kPmtiles;
    if (endsWith(output, ".mbtiles"))
      return ArchiveKind::kMbtiles;
    return makeError(ErrorCode::kInvalidInput,
                     "cannot tell the archive format from '" + output +
                         "': give --format pmtiles|mbtiles or a .pmtiles/.mbtiles name");
  }
  if (name == "pmtiles")
    return ArchiveKind::kPmtiles;
  if (name == "mbtiles")
    return ArchiveKind::kMbtiles;
  return makeError(ErrorCode::kInvalidInput,
                   "unknown archive format '" + name + "' (use pmtiles or mbtiles)");
}

base::Result<TileFormat> archiveTileFormat(const std::string& name) {
  STRAHLER_ASSIGN_OR_RETURN(const TileFormat f, parseTileFormat(name));
  if (f != TileFormat::kTerrainRgb && f != TileFormat::kTerrarium && f != TileFormat::kPng16 &&
      f != TileFormat::kRelief && f != TileFormat::kMvt)
    return makeError(ErrorCode::kInvalidInput,
                     "--tile " + name +
                         ": archives hold PNG tiles here (png for Terrain-RGB, terrarium, png16, "
                         "relief) or vector tiles (mvt)");
  return f;
}

/// --layer NAME and its parameters (as `strahler tile --layer` takes them), or none.
base::Result<std::optional<LayerOptions>> layerOptions(const CliArgs& args) {
  const auto name = args.get("--layer");
  for (const char* option : {"--species", "--azimuth", "--altitude"})
    if (!name && args.get(option))
      return makeError(ErrorCode::kInvalidInput, std::string(option) + " needs --layer");
  if (!name)
    return std::optional<LayerOptions>();
  if (const auto tile = args.get("--tile"))
    return makeError(ErrorCode::kInvalidInput,
                     "--layer " + *name + " and --tile " + *tile +
                         ": a layer archive holds the layer's grey PNGs; give one of them");
  std::map<std::string, std::string> query;
  for (const char* option : {"species", "azimuth", "altitude"})
    if (const auto value = args.get(std::string("--") + option))
      query[option] = *value;
  STRAHLER_ASSIGN_OR_RETURN(const LayerOptions layer, parseLayerOptions(*name, query));
  return std::optional<LayerOptions>(layer);
}

base::Result<ExportOptions> parseOptions(const CliArgs& args) {
  ExportOptions o;
  if (args.positional().size() != 1)
    return makeError(ErrorCode::kInvalidInput, "expected exactly one WORLD file");
  for (const char* required : {"--zooms", "-o"})
    if (!args.get(required))
      return makeError(ErrorCode::kInvalidInput, std::string("missing ") + required);
  o.output = *args.get("-o");
  o.quiet = args.has("--quiet");
  if (const std::string scheme = args.get("--scheme").value_or("web"); scheme != "web")
    return makeError(ErrorCode::kInvalidInput,
                     "--scheme " + scheme + ": archives hold Web Mercator tiles: use web");
  STRAHLER_ASSIGN_OR_RETURN(o.kind, archiveKind(args, o.output));
  STRAHLER_ASSIGN_OR_RETURN(o.layer, layerOptions(args));
  if (o.layer) {
    o.tile = TileFormat::kLayerPng;
  } else {
    STRAHLER_ASSIGN_OR_RETURN(o.tile, archiveTileFormat(args.get("--tile").value_or("png")));
  }
  STRAHLER_ASSIGN_OR_RETURN(o.zooms,
                            parseZoomRange(*args.get("--zooms"), tiling::TileScheme::kMaxWebZoom));
  if (const auto bbox = args.get("--bbox")) {
    STRAHLER_ASSIGN_OR_RETURN(o.bbox, parseBbox(*bbox));
  }
  STRAHLER_ASSIGN_OR_RETURN(const auto size,
                            args.getInt("--size", TileSizes::kRasterMin, TileSizes::kRasterMax));
  o.size = static_cast<int>(size.value_or(TileSizes::kRasterDefault));
  if (o.tile == TileFormat::kMvt && size)
    return makeError(ErrorCode::kInvalidInput, "--size: vector tiles have no size to choose");
  STRAHLER_ASSIGN_OR_RETURN(const auto threads, args.getInt("--threads", 1, 256));
  o.threads = static_cast<int>(
      threads.value_or(static_cast<long long>(std::max(1u, std::thread::hardware_concurrency()))));
  STRAHLER_ASSIGN_OR_RETURN(const auto maxTiles, args.getInt("--max-tiles", 1, 1ll << 40));
  o.maxTiles = static_cast<std::uint64_t>(maxTiles.value_or(kDefaultMaxTiles));
  return o;
}

/// Shows progress with an ETA at most every 200 ms.
void showProgress(TerminalProgress& progress, std::size_t done, std::size_t total,
                  Clock::time_point start, Clock::time_point& last) {
  const auto now = Clock::now();
  if (!progress.enabled() || now - last < std::chrono::milliseconds(200))
    return;
  last = now;
  const double elapsed = std::chrono::duration<double>(now - start).count();
  const double fraction = static_cast<double>(done) / static_cast<double>(total);
  progress.update("export", fraction,
                  std::to_string(done) + "/" + std::to_string(total) + " tiles, ETA " +
                      formatSeconds(elapsed / fraction * (1.0 - fraction)));
}

/// Renders the tiles `ids` and hands them to `sink` in that order. Stops early, with kInternal
/// "interrupted", when SIGINT or SIGTERM arrives.
base::Status renderInOrder(const TileService& service, const ExportOptions& options,
                           const std::vector<std::uint64_t>& ids, archive::TileArchiveSink& sink,
                           TerminalProgress& progress) {
  OrderedRenderer renderer(service,
                           {options.tile, options.size, options.threads,
                            options.tile == TileFormat::kMvt,
                            options.layer.value_or(LayerOptions{})},
                           ids);
  const auto start = Clock::now();
  auto last = start - std::chrono::seconds(1);
  for (std::size_t written = 0; written < ids.size();) {
    if (caughtSignal() != 0)
      return makeError(ErrorCode::kInternal, "interrupted");
    std::optional<std::string> bytes = renderer.take(std::chrono::milliseconds(100));
    if (!bytes) {
      if (auto failure = renderer.failure())
        return *failure;
      continue;
    }
    STRAHLER_RETURN_IF_ERROR(sink.addTile(archive::tileIdToZxy(ids[written]), *bytes));
    showProgress(progress, ++written, ids.size(), start, last);
  }
  progress.update("export", 1.0, std::to_string(ids.size()) + " tiles");
  return base::Ok{};
}

archive::ArchiveMetadata metadataFor(const construction::WorldData& world, const ExportOptions& o,
                                     const LonLatBox& box) {
  archive::ArchiveMetadata m;
  m.name = world.name;
  m.tileFormat = "png";
  m.tileSize = o.size;
  m.minZoom = o.zooms.first;
  m.maxZoom = o.zooms.second;
  m.west = box.west, m.south = box.south, m.east = box.east, m.north = box.north;
  m.centerLon = (box.west + box.east) / 2;
  m.centerLat = (box.south + box.north) / 2;
  m.centerZoom = std::clamp(9, o.zooms.first, o.zooms.second);
  m.version = "1.0.0";
  m.attribution = "strahler";
  switch (o.tile) {
  case TileFormat::kTerrarium:
    m.encoding = "terrarium";
    m.description = "strahler terrain (Terrarium heightmap)";
    break;
  case TileFormat::kPng16:
    m.description = "strahler terrain (16-bit grey PNG: height = value * 0.1 - 1000 m)";
    break;
  case TileFormat::kRelief: // a picture, not heights: no encoding
    m.description = "strahler terrain (colour relief: height tint times hillshade)";
    break;
  case TileFormat::kLayerPng: { // grey PNGs: the layer, its parameters, its encoding
    const LayerOptions& layer = *o.layer;
    const std::string name = kLayerNames[static_cast<std::size_t>(layer.name)];
    m.description = layerDescription(layer.name);
    m.extra.emplace_back("layer", name);
    if (const std::string query = layerQuery(layer); !query.empty())
      m.extra.emplace_back("layerQuery", query.substr(1));
    m.extra.emplace_back("layerEncoding", m.description);
    break;
  }
  case TileFormat::kMvt: // gzipped, as MBTiles' pbf and PMTiles readers expect
    m.tileFormat = "pbf";
    m.description = "strahler vector tiles (water, contours, rivers, features)";
    m.vectorLayers = vectorLayersJson(o.zooms.first, o.zooms.second);
    m.gzippedTiles = true;
    break;
  default:
    m.encoding = "mapbox";
    m.description = "strahler terrain (Terrain-RGB heightmap)";
  }
  m.extra.insert(m.extra.begin(), {{"generator", "strahler " STRAHLER_VERSION},
                                   {"generatorVersion", world.generatorVersion},
                                   {"worldId", world.cacheKey},
                                   // The served tiles' `?v=`: which world content these are.
                                   {"worldVersion", worldVersion(world)},
                                   {"seed", std::to_string(world.params.seed)},
                                   {"areaKm2", std::to_string(std::llround(world.areaKm2()))}});
  return m;
}

base::Result<std::unique_ptr<archive::TileArchiveSink>> openSink(ArchiveKind kind,
                                                                 const std::string& path) {
  if (kind == ArchiveKind::kMbtiles) {
    STRAHLER_ASSIGN_OR_RETURN(auto w, archive::MbtilesWriter::create(path));
    return std::unique_ptr<archive::TileArchiveSink>(std::move(w));
  }
  STRAHLER_ASSIGN_OR_RETURN(auto w, archive::PmtilesWriter::create(path));
  return std::unique_ptr<archive::TileArchiveSink>(std::move(w));
}

/// Renders every tile into the archive at `temporary` and renames it to its final name.
base::Status writeArchive(const TileService& service, const ExportOptions& o,
                          const std::vector<std::uint64_t>& ids,
                          const archive::ArchiveMetadata& metadata, TemporaryOutput& temporary,
                          archive::ArchiveStats& stats) {
  STRAHLER_ASSIGN_OR_RETURN(auto sink, openSink(o.kind, temporary.path()));
  {
    TerminalProgress progress(o.quiet);
    STRAHLER_RETURN_IF_ERROR(renderInOrder(service, o, ids, *sink, progress));
  }
  STRAHLER_RETURN_IF_ERROR(sink->finish(metadata));
  stats = sink->stats();
  if (caughtSignal() != 0) // arrived while the indexes were written
    return makeError(ErrorCode::kInternal, "interrupted");
  return temporary.commit();
}

/// Prints the summary line on stderr.
void printSummary(const ExportOptions& o, const archive::ArchiveStats& stats, double seconds) {
  std::error_code ec;
  const auto bytes = fs::file_size(o.output, ec);
  std::fprintf(stderr,
               "exported %llu tiles (%llu unique) to %s: %llu bytes in %.1f s, %.0f tiles/s "
               "(%d threads)\n",
               static_cast<unsigned long long>(stats.tiles),
               static_cast<unsigned long long>(stats.uniqueTiles), o.output.c_str(),
               static_cast<unsigned long long>(ec ? 0 : bytes), seconds,
               static_cast<double>(stats.tiles) / std::max(seconds, 1e-9), o.threads);
}

/// Exports `world` as `o` asks; returns the exit code (or dies by an interrupting signal).
int exportWorld(const ExportOptions& o, construction::WorldData world) {
  const LonLatBox bounds = worldBounds(world);
  const std::optional<LonLatBox> box = o.bbox ? intersect(*o.bbox, bounds) : bounds;
  if (!box)
    return fail({ErrorCode::kInvalidInput, "--bbox " + describe(*o.bbox) +
                                               " does not overlap the world (bounds " +
                                               describe(bounds) + ")"});
  const std::vector<TileRect> rects = tileRects(*box, o.zooms.first, o.zooms.second);
  if (const std::uint64_t count = countTiles(rects); count > o.maxTiles)
    return fail(makeError(
        ErrorCode::kLimitExceeded,
        "zooms " + std::to_string(o.zooms.first) + "-" + std::to_string(o.zooms.second) +
            " of this world are " + std::to_string(count) + " tiles, more than --max-tiles " +
            std::to_string(o.maxTiles) + ": lower the last zoom, give a smaller --bbox, or " +
            "raise --max-tiles if you mean it"));

  const auto start = Clock::now();
  const archive::ArchiveMetadata metadata = metadataFor(world, o, *box);
  const TileService service(std::move(world));
  const std::vector<std::uint64_t> ids = hilbertOrder(rects);
  clearCaughtSignal();
  const SignalCatcher catcher;
  TemporaryOutput temporary(o.output);
  archive::ArchiveStats stats;
  base::Status status = base::Ok{};
  try {
    status = writeArchive(service, o, ids, metadata, temporary, stats);
  } catch (const std::exception& e) { // never leave without removing the temporary file
    status = makeError(ErrorCode::kInternal, std::string("export failed: ") + e.what());
  }
  if (const int signal = caughtSignal(); signal != 0 && !status) {
    std::fprintf(stderr, "strahler: interrupted by %s: no archive written\n",
                 signal == SIGINT ? "SIGINT" : "SIGTERM");
    temporary.discard();
    return dieBy(signal);
  }
  if (!status)
    return fail(status.error());
  if (!o.quiet)
    printSummary(o, stats, std::chrono::duration<double>(Clock::now() - start).count());
  return 0;
}

} // namespace

int runExport(const std::vector<std::string>& raw) {
  auto parsed =
      CliArgs::parse("export", raw,
                     {"--format", "--scheme", "--zooms", "--bbox", "--tile", "--size", "--threads",
                      "--max-tiles", "-o", "--layer", "--species", "--azimuth", "--altitude"},
                     {"--help", "-h", "--quiet"});
  if (!parsed)
    return usageError(parsed.error(), "export");
  const CliArgs& args = parsed.value();
  if (args.has("--help") || args.has("-h"))
    return printUsage(kExportUsage);
  auto options = parseOptions(args);
  if (!options)
    return usageError(options.error(), "export");
  if (auto writable = checkWritable(options.value().output); !writable)
    return fail(writable.error());
  auto world = readWorldArgument(args.positional()[0], generateFirstHint(args.positional()[0]));
  if (!world)
    return fail(world.error());
  return exportWorld(options.value(), std::move(world).value());
}

} // namespace strahler::app
