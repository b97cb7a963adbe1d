#include "engine_heightmap.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

namespace strahler::app {

using base::ErrorCode;
using base::makeError;

base::Result<Engine> parseEngine(const std::string& name) {
  if (name == "unity")
    return Engine::kUnity;
  if (name == "unreal")
    return Engine::kUnreal;
  if (name == "godot")
    return Engine::kGodot;
  if (name == "raw")
    return Engine::kRaw;
  return makeError(ErrorCode::kInvalidInput,
                   "--engine " + name + ": use unity, unreal, godot or raw");
}

base::Result<EngineFormat> parseEngineFormat(const std::string& name) {
  if (name == "r16")
    return EngineFormat::kR16;
  if (name == "png16")
    return EngineFormat::kPng16;
  if (name == "exr")
    return EngineFormat::kExr;
  if (name == "tif")
    return EngineFormat::kTiff;
  return makeError(ErrorCode::kInvalidInput, "--format " + name + ": use r16, png16, exr or tif");
}

EngineFormat defaultFormat(Engine engine) noexcept {
  return engine == Engine::kUnreal ? EngineFormat::kPng16 : EngineFormat::kR16;
}

base::Status checkFormat(Engine engine, EngineFormat format) {
  const std::string asked =
      std::string("--engine ") + engineName(engine) + " --format " + formatName(format) + ": ";
  if (engine == Engine::kUnity && format != EngineFormat::kR16)
    return makeError(ErrorCode::kInvalidInput,
                     asked + "Unity imports 16-bit RAW heightmaps only; use --format r16");
  if (engine == Engine::kUnreal && isFloat(format))
    return makeError(ErrorCode::kInvalidInput,
                     asked + "Unreal imports 16-bit PNG or RAW heightmaps; use png16 or r16");
  if (engine == Engine::kGodot && format == EngineFormat::kTiff)
    return makeError(ErrorCode::kInvalidInput,
                     asked + "Godot cannot load TIFF; use exr, r16 or png16");
  return base::Ok{};
}

std::vector<int> validSizes(Engine engine) {
  std::vector<int> sizes;
  if (engine == Engine::kUnity) {
    for (int n = 5; n <= 12; ++n)
      sizes.push_back((1 << n) + 1);
  } else if (engine == Engine::kUnreal) {
    for (int quads : {7, 15, 31, 63, 127, 255})
      for (int sections = 1; sections <= 2; ++sections)
        for (int components = 1; components <= 32; ++components)
          sizes.push_back(quads * sections * components + 1);
    std::sort(sizes.begin(), sizes.end());
    sizes.erase(std::unique(sizes.begin(), sizes.end()), sizes.end());
  }
  return sizes;
}

namespace {

constexpr int kMinFreeSize = 2;
constexpr int kMaxFreeSize = 16385;

} // namespace

const char* engineName(Engine engine) noexcept {
  switch (engine) {
  case Engine::kUnity:
    return "unity";
  case Engine::kUnreal:
    return "unreal";
  case Engine::kGodot:
    return "godot";
  default:
    return "raw";
  }
}

bool isFloat(EngineFormat format) noexcept {
  return format == EngineFormat::kExr || format == EngineFormat::kTiff;
}

const char* formatName(EngineFormat format) noexcept {
  switch (format) {
  case EngineFormat::kR16:
    return "r16";
  case EngineFormat::kPng16:
    return "png16";
  case EngineFormat::kExr:
    return "exr";
  default:
    return "tif";
  }
}

base::Status checkSize(Engine engine, int size) {
  const std::vector<int> sizes = validSizes(engine);
  const std::string prefix =
      "--size " + std::to_string(size) + ": --engine " + engineName(engine) + " ";
  if (sizes.empty()) {
    if (size < kMinFreeSize || size > kMaxFreeSize)
      return makeError(ErrorCode::kInvalidInput, prefix + "takes 2 … 16385 samples per side");
    return base::Ok{};
  }
  const auto above = std::lower_bound(sizes.begin(), sizes.end(), size);
  if (above != sizes.end() && *above == size)
    return base::Ok{};
  std::string nearest;
  if (above != sizes.begin())
    nearest = std::to_string(*(above - 1));
  if (above != sizes.end())
    nearest += (nearest.empty() ? "" : " or ") + std::to_string(*above);
  return makeError(ErrorCode::kInvalidInput,
                   prefix + "cannot import it; the nearest valid sizes are " + nearest);
}

bool southRowFirst(Engine engine) noexcept {
  return engine == Engine::kUnity;
}

std::uint16_t quantize(double height, double minHeight, double maxHeight) noexcept {
  if (!(maxHeight > minHeight))
    return 0;
  const double t = std::clamp((height - minHeight) / (maxHeight - minHeight), 0.0, 1.0);
  return static_cast<std::uint16_t>(std::lround(t * 65535.0));
}

namespace {

/// Where 0 m lies in the file's values: the 16-bit value that quantize() gives it, or the
/// metres themselves in float files; out of the 16-bit range when the box has no sea or no land.
nlohmann::ordered_json seaLevelJson(EngineFormat format, const HeightmapExtent& e) {
  nlohmann::ordered_json j;
  j["metres"] = 0.0;
  if (isFloat(format)) {
    j["value"] = 0.0;
    j["note"] = "float32 metres: sea level is the value 0";
    return j;
  }
  if (e.minHeight > 0.0 || e.maxHeight < 0.0) {
    j["value16"] = nullptr;
    j["note"] = e.minHeight > 0.0 ? "below every height of this box (no sea in it)"
                                  : "above every height of this box (no land in it)";
    return j;
  }
  j["value16"] = quantize(0.0, e.minHeight, e.maxHeight);
  j["note"] = "the 16-bit value of 0 m: values below it are under the sea, above it land";
  return j;
}

/// For each file the export writes, in plain words, which of its rows is the north edge.
nlohmann::ordered_json northRowJson(Engine engine, const HeightmapExtent& e) {
  nlohmann::ordered_json j;
  j["heightmap"] = southRowFirst(engine)
                       ? "the last row; row 0 is the south edge (Unity: leave Flip Vertically off)"
                       : "row 0, the first row";
  if (e.splat)
    j["splatMaps"] = southRowFirst(engine)
                         ? "row 0, the first row: unlike this heightmap, whose row 0 is south"
                         : "row 0, the first row, as in the heightmap";
  return j;
}

} // namespace

std::string sidecarJson(Engine engine, EngineFormat format, const HeightmapExtent& e) {
  const double spanX = e.x1 - e.x0;
  const double spanY = e.y1 - e.y0;
  const double mppX = spanX / (e.size - 1);
  const double mppY = spanY / (e.size - 1);
  const double range = e.maxHeight - e.minHeight;
  nlohmann::ordered_json j;
  j["engine"] = engineName(engine);
  j["format"] = formatName(format);
  j["byteOrder"] = format == EngineFormat::kR16     ? "little-endian"
                   : format == EngineFormat::kPng16 ? "big-endian (PNG)"
                                                    : "float32 (the container's)";
  j["width"] = e.size;
  j["height"] = e.size;
  j["row0"] = southRowFirst(engine) ? "south" : "north";
  j["column0"] = "west";
  j["bounds"] = {{"west", e.west}, {"south", e.south}, {"east", e.east}, {"north", e.north}};
  j["localBounds"] = {{"x0", e.x0}, {"y0", e.y0}, {"x1", e.x1}, {"y1", e.y1}};
  j["metresPerPixel"] = {{"x", mppX}, {"y", mppY}};
  j["minHeight"] = e.minHeight;
  j["maxHeight"] = e.maxHeight;
  j["encoding"] = isFloat(format) ? "height = value (float32 metres)"
                                  : "height = minHeight + value / 65535 * (maxHeight - minHeight)";
  j["seaLevel"] = seaLevelJson(format, e);
  j["northRow"] = northRowJson(engine, e);
  if (e.tilesX > 1 || e.tilesY > 1)
    j["tiles"] = {{"x", e.tilesX},
                  {"y", e.tilesY},
                  {"width", (e.size - 1) / e.tilesX + 1},
                  {"height", (e.size - 1) / e.tilesY + 1},
                  {"names", "STEM_x{column}_y{row}, row 0 north; neighbours share edge samples"}};
  if (const auto& r = e.erosion)
    j["erosion"] = {{"model", "seed 004: bedrock + sediment, thermal and hydraulic erosion, "
                              "talus stabilisation; this export only, served tiles are not eroded"},
                    {"processes", r->processes},
                    {"iterations", r->iterations},
                    {"talusDegrees", r->talusDegrees},
                    {"thermalRate", r->thermalRate},
                    {"hydraulicRate", r->hydraulicRate},
                    {"toleranceM", r->toleranceM},
                    {"sweepsPerIteration", r->sweepsPerIteration},
                    {"finalSweeps", r->finalSweeps},
                    {"stable", r->stable},
                    {"cellMetres", r->cellMetres},
                    {"talusExcessM", r->talusExcessM}};
  if (const auto& sp = e.splat)
    j["splat"] = {{"layers", sp->layers},
                  {"files", sp->files},
                  {"width", sp->width},
                  {"height", sp->width},
                  {"row0", "north"},
                  {"column0", "west"},
                  {"layout", sp->layout},
                  {"sediment", sp->sediment},
                  {"weights", "8-bit; the layers' weights sum to 255 at every pixel"}};
  if (const auto& v = e.vegetation) {
    const bool unreal = engine == Engine::kUnreal;
    const char* axes = engine == Engine::kUnity    ? "x east, y up, z north"
                       : engine == Engine::kUnreal ? "X east, Y south, Z up"
                       : engine == Engine::kGodot
                           ? "x east, y up, z south (-z north)"
                           : "x east, y north, z up (the world's local frame)";
    const char* origin = engine == Engine::kUnity ? "the terrain's south-west corner (x0, y0)"
                         : engine == Engine::kRaw ? "the world's projection centre"
                                                  : "the heightmap's north-west corner (x0, y1)";
    j["vegetation"] = {{"file", v->file},
                       {"format", v->format},
                       {"count", v->count},
                       {"units", unreal ? "centimetres" : "metres"},
                       {"axes", axes},
                       {"origin", origin},
                       {"height", "absolute (the sidecar's heights), on the exported heightmap"},
                       {"columns", "id, species, x, y, z, radius, scale, yaw (radians)"},
                       {"source", "the vegetation tiles served at zoom " + std::to_string(v->zoom) +
                                      " (" + std::to_string(v->tiles) + " tiles)"}};
  }
  switch (engine) {
  case Engine::kUnity:
    j["unity"] = {{"depth", "Bit 16"},
                  {"resolution", e.size},
                  {"byteOrder", "Windows"},
                  {"flipVertically", false},
                  {"terrainSize", {{"x", spanX}, {"y", range}, {"z", spanY}}},
                  {"terrainPositionY", e.minHeight}};
    break;
  case Engine::kUnreal:
    // 0 … 65535 spans ±256 × Z scale / 100 m: Z scale = range × 100 / 512.
    j["unreal"] = {{"scaleXcm", mppX * 100},
                   {"scaleYcm", mppY * 100},
                   {"scaleZ", range * 100.0 / 512.0},
                   {"zFormula", "range (m) x 100 x 1/512"},
                   {"locationZcm", (e.minHeight + e.maxHeight) / 2 * 100}};
    break;
  case Engine::kGodot:
    // Terrain3D multiplies by the scale, then adds the offset: EXR holds metres already.
    j["godot"] = {{"heightScale", isFloat(format) ? 1.0 : range},
                  {"heightOffset", isFloat(format) ? 0.0 : e.minHeight},
                  {"r16Range", {e.minHeight, e.maxHeight}},
                  {"r16Size", {e.size, e.size}},
                  {"vertexSpacing", mppX}};
    break;
  default:
    break;
  }
  return j.dump(2) + "\n";
}

} // namespace strahler::app
