#include "heightmap_export_command.h"

#include "atomic_output.h"
#include "cli_args.h"
#include "command_support.h"
#include "engine_heightmap.h"
#include "engine_splat.h"
#include "engine_vegetation.h"
#include "export_plan.h"
#include "heightmap_erosion.h"
#include "parallel_chunks.h"
#include "terminal_progress.h"
#include "world_bounds.h"

#include "strahler/construction/world.h"
#include "strahler/encoding/grey_png.h"
#include "strahler/geometry/aabb.h"
#include "strahler/geometry/projection.h"
#include "strahler/image/image.h"
#include "strahler/store/world_file.h"
#include "strahler/tiling/tile_evaluator.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <optional>
#include <thread>

namespace strahler::app {
namespace {

using base::ErrorCode;
using base::makeError;
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr const char* kUsage =
    "usage: strahler export-heightmap WORLD.world --engine unity|unreal|godot|raw -o PATH\n"
    "                       [--bbox W,S,E,N | --local X0,Y0,X1,Y1] [--size N]\n"
    "                       [--format r16|png16|exr|tif] [--tiles AxB] [--threads N] [--quiet]\n"
    "                       [--erode thermal,hydraulic [--iterations N] [--talus DEG]] [--splat]\n"
    "                       [--vegetation csv|json]\n"
    "Writes a heightmap of the box (default: the world's land) for a game engine, N × N\n"
    "samples edge to edge, evaluated at the export's own spacing: 16-bit, the box's heights\n"
    "min..max mapped to 0..65535 (exr and tif: float32 metres), and PATH's stem + .json:\n"
    "bounds, metres per pixel, heights and the engine's import numbers. --bbox in degrees,\n"
    "--local in metres of the world's local frame (x east, y north). Engines:\n"
    "  unity   r16 (RAW, little-endian), row 0 south (Flip Vertically off), N = 2^n+1, 33..4097\n"
    "  unreal  png16 (default) or r16, row 0 north, N from its component rules (505, 1009,\n"
    "          2017, 4033, 8129, ...); --tiles AxB writes PATH_x{A}_y{B} tiles sharing edges\n"
    "  godot   r16 (default), exr or png16 for Terrain3D, row 0 north, N in 2..16385\n"
    "  raw     r16 (default), png16, exr or tif, row 0 north, N in 2..16385\n"
    "Default N: 1025 (unity, godot, raw), 1009 (unreal). --threads: default all cores; the\n"
    "bytes are the same for any count. Files are written to PATH.tmp.PID and renamed when\n"
    "complete; on an error or SIGINT/SIGTERM nothing is left. Memory: N² × 4 bytes (68 MB at\n"
    "4097²); with --tiles one row of tiles at a time (heights evaluated twice).\n"
    "--erode runs seed 004's erosion (bedrock + sediment; thermal and/or hydraulic, then talus\n"
    "stabilisation) on this export's grid, in metres, before quantising. It changes this export\n"
    "only: served tiles stay stateless and are never eroded. --iterations: rounds, 1..10000\n"
    "(default 50); --talus: degrees in (0, 90) (default 45). It needs square cells (the default\n"
    "box becomes the land's box grown to a square about its centre) and N <= 4097:\n"
    "it holds the whole grid, ~72 bytes per sample (1.2 GB at 4097²); with --tiles the whole grid\n"
    "is eroded, then cut into tiles. The sidecar's \"erosion\" records the parameters.\n"
    "--splat also writes layer weights (Ground, Rock, Sediment, Vegetation, Water; 8-bit, summing\n"
    "to 255 per pixel, row 0 north): Unity STEM_alphamap0.png (RGBA: the first four) and\n"
    "STEM_alphamap1.png (R: Water), (N-1)² texels; the others STEM_splat_LAYER.png, N² pixels\n"
    "(Unreal --tiles: STEM_splat_LAYER_x{A}_y{B}.png, as the heightmap's tiles).\n"
    "Sediment is the erosion's with --erode, else the served sediment layer's local model.\n"
    "--vegetation writes STEM_vegetation.csv|json: the plants the vegetation tiles serve\n"
    "(zoom 17) in the box, standing on this heightmap: id, species, x, y, z, radius, scale,\n"
    "yaw. Unity metres x east, y up, z north from the south-west corner; Unreal centimetres\n"
    "X east, Y south, Z up from the north-west corner; Godot metres x east, y up, z south from\n"
    "the north-west corner; raw local metres. Written a row of tiles at a time. With --tiles,\n"
    "the splat maps are tiled as the heightmap, and --splat or --vegetation keep the whole grid.\n";

/// What the command line asked for.
struct Options {
  Engine engine = Engine::kRaw;
  EngineFormat format = EngineFormat::kR16;
  int size = 0;
  int tilesX = 1, tilesY = 1;
  int threads = 1;
  std::optional<LonLatBox> bbox;
  std::optional<geometry::Aabb> local;
  std::string output;
  bool quiet = false;
  std::optional<erosion::Params> erosion;     ///< --erode's, when given.
  bool splat = false;                         ///< --splat: weight maps beside the heightmap.
  std::optional<VegetationFormat> vegetation; ///< --vegetation: the plants' file format.
};

base::Result<std::vector<double>> parseNumbers(const std::string& option, const std::string& text,
                                               std::size_t count) {
  std::vector<double> values;
  for (const std::string& part : splitCommas(text)) {
    char* end = nullptr;
    const double v = std::strtod(part.c_str(), &end);
    if (part.empty() || end != part.c_str() + part.size() || !std::isfinite(v))
      return makeError(ErrorCode::kInvalidInput,
                       option + " " + text + ": '" + part + "' is not a number");
    values.push_back(v);
  }
  if (values.size() != count)
    return makeError(ErrorCode::kInvalidInput, option + " " + text + ": expected " +
                                                   std::to_string(count) +
                                                   " numbers separated by commas");
  return values;
}

base::Result<std::pair<int, int>> parseTiles(const std::string& text) {
  int a = 0, b = 0;
  char x = 0, extra = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &a, &x, &b, &extra) != 3 || x != 'x' || a < 1 ||
      b < 1 || a > 64 || b > 64)
    return makeError(ErrorCode::kInvalidInput,
                     "--tiles " + text + ": expected AxB with A and B in 1..64, e.g. 2x2");
  return std::pair<int, int>{a, b};
}

base::Result<Options> parseOptions(const CliArgs& args) {
  Options o;
  if (args.positional().size() != 1)
    return makeError(ErrorCode::kInvalidInput, "expected exactly one WORLD file");
  for (const char* required : {"--engine", "-o"})
    if (!args.get(required))
      return makeError(ErrorCode::kInvalidInput, std::string("missing ") + required);
  o.output = *args.get("-o");
  o.quiet = args.has("--quiet");
  STRAHLER_ASSIGN_OR_RETURN(o.engine, parseEngine(*args.get("--engine")));
  o.format = defaultFormat(o.engine);
  if (const auto format = args.get("--format")) {
    STRAHLER_ASSIGN_OR_RETURN(o.format, parseEngineFormat(*format));
  }
  STRAHLER_RETURN_IF_ERROR(checkFormat(o.engine, o.format));
  STRAHLER_ASSIGN_OR_RETURN(const auto size, args.getInt("--size", 1, 1 << 20));
  o.size = static_cast<int>(size.value_or(o.engine == Engine::kUnreal ? 1009 : 1025));
  STRAHLER_RETURN_IF_ERROR(checkSize(o.engine, o.size));
  if (args.get("--bbox") && args.get("--local"))
    return makeError(ErrorCode::kInvalidInput, "give --bbox or --local, not both");
  if (const auto bbox = args.get("--bbox")) {
    STRAHLER_ASSIGN_OR_RETURN(o.bbox, parseBbox(*bbox));
  }
  if (const auto local = args.get("--local")) {
    STRAHLER_ASSIGN_OR_RETURN(const auto v, parseNumbers("--local", *local, 4));
    if (!(v[0] < v[2] && v[1] < v[3]))
      return makeError(ErrorCode::kInvalidInput,
                       "--local " + *local + ": expected X0 < X1 and Y0 < Y1");
    o.local = geometry::Aabb{{v[0], v[1]}, {v[2], v[3]}};
  }
  if (const auto tiles = args.get("--tiles")) {
    if (o.engine != Engine::kUnreal)
      return makeError(ErrorCode::kInvalidInput,
                       "--tiles: tiled heightmaps are Unreal's import; use --engine unreal");
    STRAHLER_ASSIGN_OR_RETURN(const auto t, parseTiles(*tiles));
    o.tilesX = t.first, o.tilesY = t.second;
    if ((o.size - 1) % o.tilesX != 0 || (o.size - 1) % o.tilesY != 0)
      return makeError(ErrorCode::kInvalidInput,
                       "--tiles " + *tiles + ": " + std::to_string(o.size - 1) +
                           " quads per side do not split evenly into that many tiles");
  }
  const int tileSide = std::max((o.size - 1) / o.tilesX, (o.size - 1) / o.tilesY) + 1;
  if (o.format == EngineFormat::kPng16 && tileSide > 4096)
    return makeError(ErrorCode::kInvalidInput,
                     "--format png16 holds at most 4096 samples per side here; give --tiles "
                     "(e.g. 2x2) or --format r16");
  STRAHLER_ASSIGN_OR_RETURN(o.erosion, parseErosion(args));
  o.splat = args.has("--splat");
  if (const auto vegetation = args.get("--vegetation")) {
    STRAHLER_ASSIGN_OR_RETURN(o.vegetation, parseVegetationFormat(*vegetation));
  }
  if (o.splat)
    STRAHLER_RETURN_IF_ERROR(checkSplat(o.engine, o.size, o.tilesX, o.tilesY));
  if (o.erosion && o.size > kMaxErosionSize) // before loading the world
    STRAHLER_RETURN_IF_ERROR(checkErosionGrid(o.size, geometry::Aabb{{0, 0}, {1, 1}}));
  STRAHLER_ASSIGN_OR_RETURN(const auto threads, args.getInt("--threads", 1, 256));
  o.threads = static_cast<int>(
      threads.value_or(static_cast<long long>(std::max(1u, std::thread::hardware_concurrency()))));
  return o;
}

/// The export's samples: size × size, edge to edge over box, row 0 north.
struct ExportGrid {
  geometry::Aabb box;
  int size = 0;
  double dx = 0, dy = 0;
  /// Local point of sample (row, column).
  geometry::Vec2 at(int row, int column) const noexcept {
    return {box.min.x + column * dx, box.max.y - row * dy};
  }
};

/// Evaluates rows [row0, row1) × columns [col0, col1) on `threads` threads in bands of rows
/// (each band one SampleGrid at the export's spacing): the same heights for any count.
/// Progress counts rows in `done`; stops early when a signal is caught.
std::vector<float> evaluateBlock(const tiling::TileEvaluator& evaluator, const ExportGrid& g,
                                 int row0, int row1, int col0, int col1, int threads,
                                 std::atomic<long long>& done) {
  const int width = col1 - col0;
  std::vector<float> heights(static_cast<std::size_t>(width) * (row1 - row0));
  constexpr int kBand = 8;
  const double spacing = std::min(g.dx, g.dy);
  forChunks(row0, row1, kBand, threads, [&](int r, int end) {
    if (caughtSignal() != 0)
      return;
    const int rows = end - r;
    tiling::SampleGrid grid;
    grid.width = width;
    grid.height = rows;
    grid.points.reserve(static_cast<std::size_t>(width) * rows);
    for (int i = 0; i < rows; ++i)
      for (int c = col0; c < col1; ++c)
        grid.points.push_back(g.at(r + i, c));
    for (const geometry::Vec2 p : grid.points)
      grid.bounds.add(p);
    grid.rowSpacing.assign(static_cast<std::size_t>(rows), spacing);
    const std::vector<double> h = evaluator.evaluate(grid);
    std::transform(h.begin(), h.end(),
                   heights.begin() + static_cast<std::ptrdiff_t>(r - row0) * width,
                   [](double v) { return static_cast<float>(v); });
    done.fetch_add(rows);
  });
  return heights;
}

/// The bytes of one heightmap file: `heights` (width × height, row 0 north) quantised.
base::Result<std::string> encodeFile(const Options& o, const std::vector<float>& heights, int width,
                                     int height, double minHeight, double maxHeight) {
  const bool flip = southRowFirst(o.engine);
  if (isFloat(o.format)) { // metres as they are; no engine that flips takes these formats
    if (flip)
      return makeError(ErrorCode::kInternal, "float heightmaps are written north row first");
    return image::encodeFloatImage(heights, width, height,
                                   o.format == EngineFormat::kExr ? image::FloatImageFormat::kExr
                                                                  : image::FloatImageFormat::kTiff);
  }
  std::vector<std::uint16_t> values(heights.size());
  for (int r = 0; r < height; ++r) {
    const int out = flip ? height - 1 - r : r;
    for (int c = 0; c < width; ++c)
      values[static_cast<std::size_t>(out) * width + c] =
          quantize(heights[static_cast<std::size_t>(r) * width + c], minHeight, maxHeight);
  }
  if (o.format == EngineFormat::kPng16)
    return encoding::encodeGrey16Png(values, width, height);
  std::string bytes(values.size() * 2, '\0');
  for (std::size_t i = 0; i < values.size(); ++i) { // little-endian whatever the host
    bytes[2 * i] = static_cast<char>(values[i] & 0xff);
    bytes[2 * i + 1] = static_cast<char>(values[i] >> 8);
  }
  return bytes;
}

base::Status writeBytes(TemporaryOutput& file, const std::string& bytes, const std::string& name) {
  std::ofstream out(file.path(), std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  out.close();
  if (!out)
    return makeError(ErrorCode::kIoError, "cannot write '" + name + "'");
  return base::Ok{};
}

/// PATH without its extension, and the extension.
std::pair<std::string, std::string> splitExtension(const std::string& path) {
  const fs::path p(path);
  const std::string ext = p.extension().string();
  return {path.substr(0, path.size() - ext.size()), ext};
}

/// The file of tile (x, y): PATH itself without --tiles, else STEM_x{x}_y{y}.EXT.
std::string tilePath(const Options& o, int x, int y) {
  if (o.tilesX == 1 && o.tilesY == 1)
    return o.output;
  const auto [stem, ext] = splitExtension(o.output);
  return stem + "_x" + std::to_string(x) + "_y" + std::to_string(y) + ext;
}

/// What the progress bar shows: rows evaluated, then (with --erode) erosion rounds, then the
/// final stabilisation's sweeps (whose count is only known at the end: no ETA).
struct ExportProgress {
  enum Stage { kRows, kRounds, kSweeps, kSplat, kPlants };
  std::atomic<int> stage{kRows};
  std::atomic<long long> done{0};
  std::atomic<long long> total{1};
};

/// Shows progress with an ETA per stage at most every 200 ms until `finished`.
void watchProgress(TerminalProgress& progress, const ExportProgress& state,
                   const std::atomic<bool>& finished) {
  auto start = Clock::now();
  int stage = state.stage.load();
  while (!finished.load()) {
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    if (state.stage.load() != stage)
      stage = state.stage.load(), start = Clock::now();
    const long long done = state.done.load(), total = state.total.load();
    if (stage == ExportProgress::kSweeps) {
      progress.update("erosion", 1.0, "final stabilisation, sweep " + std::to_string(done));
      continue;
    }
    const double fraction = static_cast<double>(done) / static_cast<double>(total);
    if (fraction <= 0)
      continue;
    const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
    const char* what = stage == ExportProgress::kRows     ? "export-heightmap"
                       : stage == ExportProgress::kSplat  ? "splat maps"
                       : stage == ExportProgress::kPlants ? "vegetation"
                                                          : "erosion";
    const char* unit = stage == ExportProgress::kRounds   ? " rounds"
                       : stage == ExportProgress::kPlants ? " tile rows"
                                                          : " rows";
    progress.update(what, std::min(fraction, 1.0),
                    std::to_string(done) + "/" + std::to_string(total) + unit + ", ETA " +
                        formatSeconds(elapsed / fraction * (1.0 - fraction)));
  }
}

/// The samples of tile (tx, ty) cut from `rows` (whole-width rows starting at the tile's top).
std::vector<float> cutTile(const std::vector<float>& rows, int width, int firstRow, int column0,
                           int sideX, int sideY) {
  std::vector<float> tile;
  tile.reserve(static_cast<std::size_t>(sideX + 1) * (sideY + 1));
  for (int r = firstRow; r <= firstRow + sideY; ++r)
    for (int c = column0; c <= column0 + sideX; ++c)
      tile.push_back(rows[static_cast<std::size_t>(r) * width + c]);
  return tile;
}

/// Evaluates the whole grid and erodes it (--erode): the heights, in metres; the sediment
/// thickness per sample into `sediment`.
base::Result<std::vector<float>>
erodedGrid(const Options& o, const tiling::TileEvaluator& evaluator, const ExportGrid& g,
           HeightmapExtent& extent, ExportProgress& progress, std::vector<float>& sediment) {
  std::vector<float> whole =
      evaluateBlock(evaluator, g, 0, g.size, 0, g.size, o.threads, progress.done);
  if (caughtSignal() != 0)
    return makeError(ErrorCode::kInternal, "interrupted");
  erosion::Params params = *o.erosion;
  params.threads = o.threads;
  params.onProgress = [&progress](const erosion::Progress& p) {
    if (p.finalSweeps == 0) {
      progress.done.store(p.round);
    } else {
      progress.stage.store(ExportProgress::kSweeps);
      progress.done.store(p.finalSweeps);
    }
    return caughtSignal() == 0;
  };
  progress.done.store(0);
  progress.total.store(params.iterations);
  progress.stage.store(ExportProgress::kRounds);
  extent.erosion.emplace();
  STRAHLER_ASSIGN_OR_RETURN(
      sediment, erodeExportGrid(whole, g.size, std::sqrt(g.dx * g.dy), params, *extent.erosion));
  return whole;
}

/// Writes the --splat files of the whole grid `heights` (and the erosion's `sediment`, if any).
base::Status writeSplat(const Options& o, const construction::World& world, const ExportGrid& g,
                        const std::vector<float>& heights, const std::vector<float>& sediment,
                        HeightmapExtent& extent,
                        std::vector<std::unique_ptr<TemporaryOutput>>& outputs,
                        ExportProgress& progress) {
  progress.done.store(0);
  progress.total.store(o.engine == Engine::kUnity ? g.size - 1 : g.size);
  progress.stage.store(ExportProgress::kSplat);
  STRAHLER_ASSIGN_OR_RETURN(const std::vector<SplatFile> files,
                            renderSplat(world, o.engine,
                                        SplatGrid{g.box, g.size, heights, sediment}, o.threads,
                                        progress.done, o.tilesX, o.tilesY));
  if (caughtSignal() != 0)
    return makeError(ErrorCode::kInternal, "interrupted");
  SplatRecord record;
  for (const char* name : kSplatLayerNames)
    record.layers.emplace_back(name);
  record.width = o.engine == Engine::kUnity ? g.size - 1 : g.size;
  record.layout = o.engine == Engine::kUnity
                      ? "Unity alphamaps: alphamap0 RGBA = Ground, Rock, Sediment, Vegetation; "
                        "alphamap1 R = Water (G, B, A 0); texel = mean of its 4 corner samples"
                  : o.tilesX > 1 || o.tilesY > 1
                      ? "one 8-bit grey PNG per layer and tile (STEM_splat_LAYER_x{A}_y{B}.png), "
                        "one pixel per heightmap sample, cut as the heightmap's tiles"
                      : "one 8-bit grey PNG per layer, one pixel per heightmap sample";
  record.sediment = sediment.empty() ? "proxy: the served sediment layer's local model "
                                       "(layers::sedimentThickness), no --erode"
                                     : "the erosion's sediment S (--erode)";
  const std::string stem = splitExtension(o.output).first;
  for (const SplatFile& file : files) {
    const std::string name = stem + file.suffix;
    outputs.push_back(std::make_unique<TemporaryOutput>(name));
    STRAHLER_RETURN_IF_ERROR(writeBytes(*outputs.back(), file.bytes, name));
    record.files.push_back(fs::path(name).filename().string());
  }
  extent.splat = std::move(record);
  return base::Ok{};
}

/// Writes the --vegetation file: the served plants in the box, standing on `heights`.
base::Status writePlants(const Options& o, const construction::World& world,
                         const tiling::TileEvaluator& evaluator, const ExportGrid& g,
                         const std::vector<float>& heights, HeightmapExtent& extent,
                         std::vector<std::unique_ptr<TemporaryOutput>>& outputs,
                         ExportProgress& progress) {
  progress.done.store(0);
  progress.total.store(1);
  progress.stage.store(ExportProgress::kPlants);
  const bool csv = *o.vegetation == VegetationFormat::kCsv;
  const std::string name =
      splitExtension(o.output).first + "_vegetation" + (csv ? ".csv" : ".json");
  outputs.push_back(std::make_unique<TemporaryOutput>(name));
  std::ofstream out(outputs.back()->path(), std::ios::binary);
  STRAHLER_ASSIGN_OR_RETURN(const VegetationCount count,
                            writeVegetation(world, evaluator, o.engine, *o.vegetation,
                                            VegetationGrid{g.box, g.size, heights}, o.threads, out,
                                            progress.total, progress.done,
                                            [] { return caughtSignal() != 0; }));
  out.close();
  if (!out)
    return makeError(ErrorCode::kIoError, "cannot write '" + name + "'");
  extent.vegetation = VegetationRecord{fs::path(name).filename().string(), csv ? "csv" : "json",
                                       count.instances, kVegetationZoom, count.tiles};
  return base::Ok{};
}

/// Evaluates (and with --erode erodes) and writes every file (temporaries in `outputs`,
/// committed by the caller).
base::Status writeFiles(const Options& o, const construction::World& world,
                        const tiling::TileEvaluator& evaluator, const ExportGrid& g,
                        HeightmapExtent& extent,
                        std::vector<std::unique_ptr<TemporaryOutput>>& outputs,
                        ExportProgress& progress) {
  const bool tiled = o.tilesX > 1 || o.tilesY > 1;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  std::vector<float> whole, sediment;
  if (o.erosion) {
    STRAHLER_ASSIGN_OR_RETURN(whole, erodedGrid(o, evaluator, g, extent, progress, sediment));
  } else if (!tiled || o.splat || o.vegetation) { // the whole grid: splat and plants read it
    progress.total.store(o.size);
    whole = evaluateBlock(evaluator, g, 0, g.size, 0, g.size, o.threads, progress.done);
    if (caughtSignal() != 0)
      return makeError(ErrorCode::kInternal, "interrupted");
  } else { // tiled: the heights' range first, streamed a tile row at a time
    progress.total.store(2LL * (o.size + o.tilesY - 1));
    const int band = (g.size - 1) / o.tilesY + 1;
    for (int r0 = 0; r0 < g.size - 1; r0 += band - 1) {
      const int r1 = std::min(g.size, r0 + band);
      const std::vector<float> h =
          evaluateBlock(evaluator, g, r0, r1, 0, g.size, o.threads, progress.done);
      if (caughtSignal() != 0)
        return makeError(ErrorCode::kInternal, "interrupted");
      const auto [mn, mx] = std::minmax_element(h.begin(), h.end());
      lo = std::min(lo, static_cast<double>(*mn));
      hi = std::max(hi, static_cast<double>(*mx));
    }
  }
  if (!whole.empty()) {
    const auto [mn, mx] = std::minmax_element(whole.begin(), whole.end());
    lo = *mn, hi = *mx;
  }
  extent.minHeight = lo, extent.maxHeight = hi;
  if (!tiled) {
    STRAHLER_ASSIGN_OR_RETURN(const std::string bytes,
                              encodeFile(o, whole, g.size, g.size, lo, hi));
    outputs.push_back(std::make_unique<TemporaryOutput>(o.output));
    STRAHLER_RETURN_IF_ERROR(writeBytes(*outputs.back(), bytes, o.output));
  }
  const int sideX = (g.size - 1) / o.tilesX, sideY = (g.size - 1) / o.tilesY;
  for (int ty = 0; tiled && ty < o.tilesY; ++ty) {
    std::vector<float> rows; // the tile row's samples, unless the whole grid is in memory
    if (whole.empty()) {
      rows = evaluateBlock(evaluator, g, ty * sideY, ty * sideY + sideY + 1, 0, g.size, o.threads,
                           progress.done);
      if (caughtSignal() != 0)
        return makeError(ErrorCode::kInternal, "interrupted");
    }
    for (int tx = 0; tx < o.tilesX; ++tx) {
      const std::vector<float> tile =
          whole.empty() ? cutTile(rows, g.size, 0, tx * sideX, sideX, sideY)
                        : cutTile(whole, g.size, ty * sideY, tx * sideX, sideX, sideY);
      STRAHLER_ASSIGN_OR_RETURN(const std::string bytes,
                                encodeFile(o, tile, sideX + 1, sideY + 1, lo, hi));
      const std::string name = tilePath(o, tx, ty);
      outputs.push_back(std::make_unique<TemporaryOutput>(name));
      STRAHLER_RETURN_IF_ERROR(writeBytes(*outputs.back(), bytes, name));
    }
  }
  if (o.splat)
    STRAHLER_RETURN_IF_ERROR(writeSplat(o, world, g, whole, sediment, extent, outputs, progress));
  if (o.vegetation)
    STRAHLER_RETURN_IF_ERROR(writePlants(o, world, evaluator, g, whole, extent, outputs, progress));
  return base::Ok{};
}

/// The local box to export, or an error when it misses the world's land.
base::Result<geometry::Aabb> exportBox(const Options& o, const construction::WorldData& world,
                                       const geometry::LocalProjection& projection) {
  geometry::Aabb land;
  for (const geometry::Polygon& p : world.land)
    for (geometry::Vec2 v : p.outer)
      land.add(v);
  geometry::Aabb box = land;
  if (o.erosion) // the erosion wants square cells
    box = squareAbout(land);
  std::string asked;
  if (o.local) {
    box = *o.local;
    asked = "--local";
  } else if (o.bbox) {
    box = geometry::Aabb{};
    const LonLatBox& b = *o.bbox;
    for (int i = 0; i <= 8; ++i) { // the edges' curves in the local frame
      const double t = i / 8.0;
      box.add(projection.forward({b.west + t * (b.east - b.west), b.south}));
      box.add(projection.forward({b.west + t * (b.east - b.west), b.north}));
      box.add(projection.forward({b.west, b.south + t * (b.north - b.south)}));
      box.add(projection.forward({b.east, b.south + t * (b.north - b.south)}));
    }
    asked = "--bbox " + describe(b);
  }
  if (box.max.x <= land.min.x || box.min.x >= land.max.x || box.max.y <= land.min.y ||
      box.min.y >= land.max.y) {
    char text[160];
    std::snprintf(
        text, sizeof text, " does not overlap the world's land (local %.0f,%.0f,%.0f,%.0f m; %s)",
        land.min.x, land.min.y, land.max.x, land.max.y, describe(worldBounds(world)).c_str());
    return makeError(ErrorCode::kInvalidInput, asked + text);
  }
  return box;
}

int exportHeightmap(const Options& o, construction::WorldData data) {
  const geometry::LocalProjection projection(data.projectionCenter.x, data.projectionCenter.y);
  auto box = exportBox(o, data, projection);
  if (!box)
    return fail(box.error());
  ExportGrid g{box.value(), o.size, box.value().size().x / (o.size - 1),
               box.value().size().y / (o.size - 1)};
  if (o.erosion)
    if (auto square = checkErosionGrid(o.size, g.box); !square)
      return fail(square.error());
  HeightmapExtent extent;
  extent.x0 = g.box.min.x, extent.y0 = g.box.min.y, extent.x1 = g.box.max.x,
  extent.y1 = g.box.max.y, extent.size = o.size;
  extent.tilesX = o.tilesX, extent.tilesY = o.tilesY;
  geometry::Aabb degrees;
  for (const geometry::Vec2 corner :
       {g.box.min, g.box.max, geometry::Vec2{g.box.min.x, g.box.max.y},
        geometry::Vec2{g.box.max.x, g.box.min.y}})
    degrees.add(projection.inverse(corner));
  extent.west = degrees.min.x, extent.south = degrees.min.y, extent.east = degrees.max.x,
  extent.north = degrees.max.y;

  const auto start = Clock::now();
  const construction::World world(std::move(data));
  const tiling::TileEvaluator evaluator(world);
  clearCaughtSignal();
  const SignalCatcher catcher;
  std::vector<std::unique_ptr<TemporaryOutput>> outputs;
  ExportProgress state;
  state.total.store(o.size);
  base::Status status = base::Ok{};
  {
    TerminalProgress progress(o.quiet);
    std::atomic<bool> finished{false};
    std::thread watcher;
    if (progress.enabled())
      watcher = std::thread([&] { watchProgress(progress, state, finished); });
    try {
      status = writeFiles(o, world, evaluator, g, extent, outputs, state);
    } catch (const std::exception& e) { // never leave without removing the temporary files
      status = makeError(ErrorCode::kInternal, std::string("export failed: ") + e.what());
    }
    finished.store(true);
    if (watcher.joinable())
      watcher.join();
  }
  const std::string sidecar = splitExtension(o.output).first + ".json";
  TemporaryOutput sidecarFile(sidecar);
  if (status)
    status = writeBytes(sidecarFile, sidecarJson(o.engine, o.format, extent), sidecar);
  if (const int signal = caughtSignal(); signal != 0) {
    std::fprintf(stderr, "strahler: interrupted by %s: no heightmap written\n",
                 signal == SIGINT ? "SIGINT" : "SIGTERM");
    for (auto& file : outputs)
      file->discard();
    sidecarFile.discard();
    return dieBy(signal);
  }
  for (auto& file : outputs)
    if (status)
      status = file->commit();
  if (status)
    status = sidecarFile.commit();
  if (!status)
    return fail(status.error());
  if (!o.quiet)
    std::fprintf(stderr,
                 "exported a %d × %d heightmap (%zu file%s, %s) to %s in %.1f s (%d threads); "
                 "heights %.2f … %.2f m; sidecar %s\n",
                 o.size, o.size, outputs.size(), outputs.size() == 1 ? "" : "s",
                 formatName(o.format), o.output.c_str(),
                 std::chrono::duration<double>(Clock::now() - start).count(), o.threads,
                 extent.minHeight, extent.maxHeight, sidecar.c_str());
  return 0;
}

} // namespace

int runExportHeightmap(const std::vector<std::string>& raw) {
  auto parsed =
      CliArgs::parse("export-heightmap", raw,
                     {"--engine", "--format", "--size", "--bbox", "--local", "--tiles", "--threads",
                      "-o", "--erode", "--iterations", "--talus", "--vegetation"},
                     {"--help", "-h", "--quiet", "--splat"});
  if (!parsed)
    return usageError(parsed.error(), "export-heightmap");
  const CliArgs& args = parsed.value();
  if (args.has("--help") || args.has("-h"))
    return printUsage(kUsage);
  auto options = parseOptions(args);
  if (!options) // a refused value is a wrong command line, like an unparsable one
    return usageError(options.error(), "export-heightmap");
  if (auto writable = checkWritable(options.value().output); !writable)
    return fail(writable.error());
  auto world = readWorldArgument(args.positional()[0], generateFirstHint(args.positional()[0]));
  if (!world)
    return fail(world.error());
  return exportHeightmap(options.value(), std::move(world).value());
}

} // namespace strahler::app
