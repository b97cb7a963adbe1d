#pragma once

#include "cli_args.h"

#include "strahler/input/limits.h"

namespace strahler::app {

/// The options that set the size limits of a coastline (generate, serve).
inline constexpr const char* kMaxAreaOption = "--max-area-km2";
inline constexpr const char* kMaxExtentOption = "--max-extent-km";

/// The input limits with --max-area-km2 (whole km², 1..100,000,000) and --max-extent-km (whole
/// km, 1..40,000) applied where given: for worlds larger than the defaults on bigger machines.
base::Result<input::InputLimits> worldLimits(const CliArgs& args);

} // namespace strahler::app
