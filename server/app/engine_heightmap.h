#pragma once
// The rules of game engines' heightmap imports (sizes, formats, byte order, orientation) and
// the 16-bit quantisation and sidecar of `strahler export-heightmap`.

#include "strahler/base/result.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace strahler::app {

/// The engine an export is made for.
enum class Engine { kUnity, kUnreal, kGodot, kRaw };

/// The heightmap file formats export-heightmap writes.
enum class EngineFormat {
  kR16,   ///< 16-bit unsigned samples, little-endian, no header.
  kPng16, ///< 16-bit grey PNG.
  kExr,   ///< OpenEXR, one float32 channel of metres (not quantised).
  kTiff,  ///< TIFF, one float32 channel of metres (not quantised).
};

/// The engine's --engine name.
const char* engineName(Engine engine) noexcept;
/// Parses "unity", "unreal", "godot" or "raw".
base::Result<Engine> parseEngine(const std::string& name);
/// Parses --format: "r16", "png16", "exr" or "tif".
base::Result<EngineFormat> parseEngineFormat(const std::string& name);
/// The format an engine gets without --format (Unity and Godot r16, Unreal png16, raw r16).
EngineFormat defaultFormat(Engine engine) noexcept;
/// kInvalidInput when `engine` cannot import `format`: Unity reads RAW only, Unreal 16-bit
/// PNG or RAW, Godot (Terrain3D) r16, PNG or EXR but not TIFF.
base::Status checkFormat(Engine engine, EngineFormat format);

/// Every valid side length of `engine`, ascending: Unity 2^n + 1 for 33 … 4097; Unreal
/// quads-per-section (7, 15, 31, 63, 127, 255) × sections per component (1, 2) × components
/// (1 … 32) + 1; Godot and raw any side in 2 … 16385 (returned empty).
std::vector<int> validSizes(Engine engine);
/// kInvalidInput naming the nearest valid sizes below and above when `size` is not valid.
base::Status checkSize(Engine engine, int size);

/// True when the engine reads row 0 as the southern edge (Unity's RAW, "Flip Vertically" off);
/// the others read row 0 as the northern edge (north up, x east).
bool southRowFirst(Engine engine) noexcept;

/// True for the float formats (EXR, TIFF), which hold metres instead of 16-bit values.
bool isFloat(EngineFormat format) noexcept;
/// The format's --format name.
const char* formatName(EngineFormat format) noexcept;

/// Heights mapped linearly from [minHeight, maxHeight] to 0 … 65535 (rounded; a flat box
/// gives 0 everywhere).
std::uint16_t quantize(double height, double minHeight, double maxHeight) noexcept;

/// The erosion an export went through (export-heightmap --erode), for the sidecar.
struct ErosionRecord {
  std::string processes;      ///< "thermal", "hydraulic" or "thermal,hydraulic".
  int iterations = 0;         ///< Rounds.
  double talusDegrees = 0;    ///< The stabilisation's talus angle.
  double thermalRate = 0;     ///< m of bedrock weathered per round at I·tanβ = 1.
  double hydraulicRate = 0;   ///< m carried downhill per round at H·tanβ = 1.
  double toleranceM = 0;      ///< The final stabilisation's tolerance, m.
  int sweepsPerIteration = 0; ///< Stabilisation sweeps in each round.
  int finalSweeps = 0;        ///< Sweeps the final stabilisation took.
  bool stable = false;        ///< True when the final stabilisation reached toleranceM.
  double cellMetres = 0;      ///< The erosion's cell size, m.
  double talusExcessM = 0;    ///< erosion::talusExcess of the result, m (≤ toleranceM).
};

/// The splat maps an export wrote (export-heightmap --splat), for the sidecar.
struct SplatRecord {
  std::vector<std::string> layers; ///< Layer names, in file / channel order.
  std::vector<std::string> files;  ///< File names (no folder), in order.
  int width = 0;                   ///< Pixels per side of each file.
  std::string layout;              ///< How layers map to files and channels.
  std::string sediment;            ///< Where the sediment layer comes from.
};

/// The vegetation instances an export wrote (export-heightmap --vegetation), for the sidecar.
struct VegetationRecord {
  std::string file;    ///< File name (no folder).
  std::string format;  ///< "csv" or "json".
  long long count = 0; ///< Plants written.
  int zoom = 0;        ///< The Web Mercator zoom of the vegetation tiles they come from.
  long long tiles = 0; ///< Vegetation tiles placed.
};

/// What a sidecar states about one export.
struct HeightmapExtent {
  double west = 0, south = 0, east = 0, north = 0; ///< Degrees (the box's corners' bounds).
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;           ///< Local metres.
  int size = 0;                                    ///< Samples per side.
  double minHeight = 0, maxHeight = 0;             ///< m.
  int tilesX = 1, tilesY = 1;                      ///< Unreal's --tiles (1 × 1: one file).
  std::optional<ErosionRecord> erosion;            ///< Set when the export was eroded.
  std::optional<SplatRecord> splat;                ///< Set when splat maps were written.
  std::optional<VegetationRecord> vegetation;      ///< Set when instances were written.
};

/// The sidecar JSON (bounds, metres per pixel, heights, the engine's import numbers).
std::string sidecarJson(Engine engine, EngineFormat format, const HeightmapExtent& extent);

} // namespace strahler::app
