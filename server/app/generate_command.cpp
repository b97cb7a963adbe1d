#include "generate_command.h"

#include "cli_args.h"
#include "command_support.h"
#include "terminal_progress.h"
#include "world_limits.h"
#include "world_loader.h"
#include "world_summary.h"

#include "strahler/analysis/network_analysis.h"
#include "strahler/blocks/block_set.h"
#include "strahler/image/image.h"
#include "strahler/input/world_spec.h"
#include "strahler/render/network_image.h"
#include "strahler/render/rivers_geojson.h"
#include "strahler/store/world_file.h"

#include <cstdio>
#include <optional>

namespace strahler::app {
namespace {

constexpr int kDefaultImageSize = 1600;

/// The error for an output file name generate cannot write.
std::string outputNameError(const std::string& path) {
  return "output '" + path +
         "': use a .world (world file), .geojson (river network) or .png (network image) file "
         "name";
}

/// The picture of the network over its blocks; blocks are rebuilt from the graph (a few ms).
base::Status writeNetworkImage(const std::string& path, const input::WorldSpec& spec,
                               const construction::WorldData& world, int size) {
  const geometry::PolygonIndex land(spec.land);
  STRAHLER_ASSIGN_OR_RETURN(blocks::BlockSet blocks, blocks::buildBlocks(world.network, land));
  const analysis::NetworkAnalysis analysis =
      analysis::analyzeNetwork(spec, land, world.network, blocks);
  return image::writePng(
      path, render::drawNetworkImage(spec.land, world.network, blocks, analysis, size));
}

/// Writes the outputs the user asked for.
base::Status writeOutputs(const CliArgs& args, const input::WorldSpec& spec,
                          const construction::WorldData& world, int imageSize) {
  if (auto o = args.get("-o")) {
    if (endsWith(*o, ".world")) {
      STRAHLER_RETURN_IF_ERROR(store::writeWorldFile(*o, world));
    } else if (endsWith(*o, ".png")) {
      STRAHLER_RETURN_IF_ERROR(writeNetworkImage(*o, spec, world, imageSize));
    } else if (endsWith(*o, ".geojson") || endsWith(*o, ".json")) {
      STRAHLER_RETURN_IF_ERROR(writeTextFile(*o, render::riversGeoJson(world, spec.projection)));
    } else {
      return base::makeError(base::ErrorCode::kInvalidInput, outputNameError(*o));
    }
  }
  if (auto image = args.get("--image"))
    STRAHLER_RETURN_IF_ERROR(writeNetworkImage(*image, spec, world, imageSize));
  return base::Ok{};
}

} // namespace

const char* generateUsage() noexcept {
  return "usage: strahler generate [--coast FILE.geojson] [--params FILE.json] [--mouths "
         "FILE.geojson]\n"
         "                         [--features FILE.geojson] [--grower grammar|dla]\n"
         "                         [--seed N] [--cache-dir DIR] [-o "
         "OUT.world|OUT.geojson|OUT.png]\n"
         "                         [--image OUT.png] [--image-size PX] [--max-area-km2 N]\n"
         "                         [--max-extent-km N] [--repair] [--json] [--quiet]\n"
         "Generates the world of a coastline (default: the embedded island), or loads it from the\n"
         "cache when the same inputs were generated before, and prints a summary. -o writes the\n"
         "world file, the river network as GeoJSON, or the network image (.png); --image writes\n"
         "the network over its blocks (PX: 64..8192, default 1600). The cache directory defaults\n"
         "to $STRAHLER_CACHE_DIR, $XDG_CACHE_HOME/strahler or ~/.cache/strahler.\n"
         "--max-area-km2 N (default 250000) and --max-extent-km N (default 2000) raise or lower\n"
         "the size a coastline may have (land area, longest side of its bounding box).\n"
         "--repair mends a coastline's self-intersections, spikes, duplicate points, overlaps\n"
         "and ring orientation instead of refusing it, and lists each change on stderr (kind,\n"
         "lon/lat, area moved in km²; in the --json summary under \"repairs\").\n"
         "--features FILE.geojson: the artist's vector map, GeoJSON Features whose \"kind\" is\n"
         "\"mountain\" (Point; elevation, radius in m), \"ridge\" (LineString; elevation) or\n"
         "\"river\" (LineString from source to mouth on a shore; name). Faults (a river off the\n"
         "land or crossing another, a mountain in the sea, ...) are refused with exit code 1.\n"
         "--grower grammar|dla: how the river network grows: the paper's open grammar (default)\n"
         "or diffusion-limited aggregation (seed 001; docs/growers.md); params.json may set it\n"
         "as \"grower\".\n";
}

int runGenerate(const std::vector<std::string>& rawArgs) {
  auto parsed = CliArgs::parse("generate", rawArgs,
                               {"--coast", "--params", "--mouths", "--features", "--grower",
                                "--seed", "--cache-dir", "-o", "--image", "--image-size",
                                kMaxAreaOption, kMaxExtentOption},
                               {"--json", "--quiet", "--repair", "--help", "-h"});
  if (!parsed)
    return usageError(parsed.error(), "generate");
  const CliArgs& args = parsed.value();
  if (args.has("--help") || args.has("-h"))
    return printUsage(generateUsage());
  if (!args.positional().empty()) {
    const std::string& extra = args.positional()[0];
    const bool geojson = endsWith(extra, ".geojson") || endsWith(extra, ".json");
    return usageError({base::ErrorCode::kInvalidInput,
                       "unexpected argument '" + extra + "'" +
                           (geojson ? "; a coastline is given with --coast " + extra : "")},
                      "generate");
  }
  auto seed = args.getU64("--seed");
  if (!seed)
    return usageError(seed.error(), "generate");
  auto imageSize = args.getInt("--image-size", 64, 8192);
  if (!imageSize)
    return usageError(imageSize.error(), "generate");

  std::optional<input::NetworkGrower> grower;
  if (auto name = args.get("--grower")) {
    auto named = input::parseGrower(*name);
    if (!named)
      return usageError(named.error(), "generate");
    grower = named.value();
  }
  if (auto o = args.get("-o"); o && !endsWith(*o, ".world") && !endsWith(*o, ".png") &&
                               !endsWith(*o, ".geojson") && !endsWith(*o, ".json"))
    return usageError({base::ErrorCode::kInvalidInput, outputNameError(*o)}, "generate");

  input::WorldSources sources;
  sources.coastPath = args.get("--coast").value_or("");
  sources.paramsPath = args.get("--params").value_or("");
  sources.mouthsPath = args.get("--mouths").value_or("");
  sources.featuresPath = args.get("--features").value_or("");
  sources.seed = seed.value();
  sources.repair = args.has("--repair");

  auto limits = worldLimits(args);
  if (!limits)
    return usageError(limits.error(), "generate");
  auto spec = input::loadWorldSpec(sources, limits.value());
  if (!spec)
    return fail(spec.error());
  if (grower)
    spec.value().params.grower = *grower;
  printRepairsAndWarnings(spec.value());
  base::StageTimer timer;
  TerminalProgress progress(args.has("--quiet"));
  auto world =
      loadOrGenerateWorld(spec.value(), args.get("--cache-dir").value_or(defaultCacheDir()),
                          progress.callback(), &timer);
  if (!world)
    return fail(world.error());
  for (const std::string& warning : world.value().warnings)
    std::fprintf(stderr, "strahler: warning: %s\n", warning.c_str());
  const construction::WorldData& data = world.value().data;
  if (auto written = writeOutputs(args, spec.value(), data,
                                  static_cast<int>(imageSize.value().value_or(kDefaultImageSize)));
      !written)
    return fail(written.error());

  WorldSummary summary = summarize(data, store::encodeWorld(data).size());
  summary.filePath = world.value().path;
  summary.fromCache = world.value().fromCache;
  summary.repairs = spec.value().repairs;
  if (world.value().fromCache)
    summary.stages = timer.stages();
  if (!args.has("--quiet") || args.has("--json"))
    std::fputs((args.has("--json") ? toJson(summary) + "\n" : toText(summary)).c_str(), stdout);
  return 0;
}

} // namespace strahler::app
