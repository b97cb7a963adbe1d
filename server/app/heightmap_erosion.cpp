#include "heightmap_erosion.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace strahler::app {

using base::ErrorCode;
using base::makeError;

base::Result<std::optional<erosion::Params>> parseErosion(const CliArgs& args) {
  const auto erode = args.get("--erode");
  if (!erode) {
    for (const char* option : {"--iterations", "--talus"})
      if (args.get(option))
        return makeError(ErrorCode::kInvalidInput,
                         std::string(option) + " needs --erode thermal,hydraulic (or one of them)");
    return std::optional<erosion::Params>();
  }
  erosion::Params p;
  p.thermal = p.hydraulic = false;
  for (const std::string& name : splitCommas(*erode)) {
    if (name == "thermal")
      p.thermal = true;
    else if (name == "hydraulic")
      p.hydraulic = true;
    else
      return makeError(ErrorCode::kInvalidInput, "--erode " + *erode + ": unknown process '" +
                                                     name +
                                                     "'; use thermal, hydraulic or both "
                                                     "(thermal,hydraulic)");
  }
  if (const auto text = args.get("--iterations")) {
    char* end = nullptr;
    const long long n = std::strtoll(text->c_str(), &end, 10);
    if (text->empty() || *end != '\0' || n < 1 || n > erosion::Params::kMaxIterations)
      return makeError(ErrorCode::kInvalidInput,
                       "--iterations " + *text + ": give 1 … " +
                           std::to_string(erosion::Params::kMaxIterations) +
                           " rounds (leave out --erode for the plain heightmap)");
    p.iterations = static_cast<int>(n);
  }
  if (const auto text = args.get("--talus")) {
    char* end = nullptr;
    const double degrees = std::strtod(text->c_str(), &end);
    if (text->empty() || *end != '\0' || !(degrees > 0.0 && degrees < 90.0))
      return makeError(ErrorCode::kInvalidInput,
                       "--talus " + *text + ": the talus angle is in degrees, in (0, 90)");
    p.talusDegrees = degrees;
  }
  return std::optional<erosion::Params>(p);
}

geometry::Aabb squareAbout(const geometry::Aabb& box) {
  const geometry::Vec2 c = box.center();
  const double half = std::max(box.size().x, box.size().y) / 2;
  return geometry::Aabb{{c.x - half, c.y - half}, {c.x + half, c.y + half}};
}

base::Status checkErosionGrid(int size, const geometry::Aabb& box) {
  if (size > kMaxErosionSize)
    return makeError(ErrorCode::kInvalidInput,
                     "--erode --size " + std::to_string(size) +
                         ": the erosion holds the whole grid (about 72 bytes per sample), so "
                         "it takes at most " +
                         std::to_string(kMaxErosionSize) + " samples per side (1.2 GB)");
  const double dx = box.size().x / (size - 1), dy = box.size().y / (size - 1);
  if (std::abs(dx - dy) > kErosionSquareTolerance * std::max(dx, dy)) {
    const geometry::Aabb square = squareAbout(box);
    char text[300];
    std::snprintf(text, sizeof text,
                  "--erode: the erosion needs square cells, and this box gives %.2f × %.2f m; "
                  "give a square box, e.g. --local %.0f,%.0f,%.0f,%.0f (the square around it)",
                  dx, dy, square.min.x, square.min.y, square.max.x, square.max.y);
    return makeError(ErrorCode::kInvalidInput, text);
  }
  return base::Ok{};
}

std::string erosionProcesses(const erosion::Params& params) {
  if (params.thermal && params.hydraulic)
    return "thermal,hydraulic";
  return params.thermal ? "thermal" : "hydraulic";
}

base::Result<std::vector<float>> erodeExportGrid(std::vector<float>& heights, int size,
                                                 double spacing, const erosion::Params& params,
                                                 ErosionRecord& record) {
  erosion::Layers layers;
  {
    const std::vector<double> metres(heights.begin(), heights.end());
    STRAHLER_ASSIGN_OR_RETURN(layers, erosion::erode(metres, size, size, spacing, params));
  }
  std::vector<float> sediment(heights.size());
  for (std::size_t i = 0; i < heights.size(); ++i) {
    heights[i] = static_cast<float>(layers.bedrock[i] + layers.sediment[i]);
    sediment[i] = static_cast<float>(layers.sediment[i]);
  }
  record.processes = erosionProcesses(params);
  record.iterations = params.iterations;
  record.talusDegrees = params.talusDegrees;
  record.thermalRate = params.thermalRate;
  record.hydraulicRate = params.hydraulicRate;
  record.toleranceM = params.toleranceM;
  record.sweepsPerIteration = params.sweepsPerIteration;
  record.finalSweeps = layers.finalSweeps;
  record.stable = layers.stable;
  record.cellMetres = spacing;
  record.talusExcessM = erosion::talusExcess(layers, params.talusDegrees);
  return sediment;
}

} // namespace strahler::app
