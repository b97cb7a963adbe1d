#pragma once
// `strahler export-heightmap --erode`: the options, their checks, and the seed's erosion
// (core/erosion) run on the export's grid. It changes that export only: served tiles never
// erode.

#include "cli_args.h"
#include "engine_heightmap.h"

#include "strahler/base/result.h"
#include "strahler/erosion/erosion.h"
#include "strahler/geometry/aabb.h"

#include <optional>
#include <string>
#include <vector>

namespace strahler::app {

/// The largest side --erode takes: the erosion holds the whole grid, about nine doubles
/// (72 bytes) per sample, 1.2 GB at 4097² (8129² would need 4.8 GB).
inline constexpr int kMaxErosionSize = 4097;
/// The largest relative difference between the grid's x and y spacing --erode takes (the
/// erosion's cells are square).
inline constexpr double kErosionSquareTolerance = 0.01;

/// --erode thermal|hydraulic|thermal,hydraulic with --iterations N (1 … kMaxIterations,
/// default 50) and --talus DEG (in (0, 90), default 45); nullopt without --erode.
/// kInvalidInput naming the option for an unknown process, 0 or too many iterations, a talus
/// outside (0, 90), or --iterations / --talus without --erode.
base::Result<std::optional<erosion::Params>> parseErosion(const CliArgs& args);

/// The square with `box`'s centre whose side is `box`'s longer side (it holds all of `box`).
geometry::Aabb squareAbout(const geometry::Aabb& box);

/// kInvalidInput when a size × size grid over `box` (local metres) cannot be eroded: a side
/// above kMaxErosionSize, or cells not square within kErosionSquareTolerance (the message
/// proposes the square --local around the box's centre that holds it).
base::Status checkErosionGrid(int size, const geometry::Aabb& box);

/// "thermal", "hydraulic" or "thermal,hydraulic".
std::string erosionProcesses(const erosion::Params& params);

/// Erodes `heights` (size × size, row 0 north, m) in place into the surface B + S, with cells
/// of `spacing` m; returns the sediment S per sample (m) and fills `record` for the sidecar.
/// Errors: erosion::erode's (including "erosion: cancelled" from params.onProgress).
base::Result<std::vector<float>> erodeExportGrid(std::vector<float>& heights, int size,
                                                 double spacing, const erosion::Params& params,
                                                 ErosionRecord& record);

} // namespace strahler::app
