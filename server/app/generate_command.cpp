#include "generate_command.h"

#include "cli_args.h"
#include "terminal_progress.h"
#include "world_summary.h"

#include "strahler/analysis/hydrology.h"
#include "strahler/image/image.h"
#include "strahler/input/world_spec.h"
#include "strahler/render/network_image.h"
#include "strahler/render/rivers_geojson.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace strahler::app {
namespace {

constexpr int kDefaultImageSize = 1600;

base::Status writeTextFile(const std::string& path, const std::string& text) {
  const std::string temporary = path + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out)
      return base::makeError(base::ErrorCode::kIoError, "cannot write '" + path + "'");
    out << text;
    if (!out.flush())
      return base::makeError(base::ErrorCode::kIoError, "cannot write '" + path + "'");
  }
  std::error_code ec;
  std::filesystem::rename(temporary, path, ec);
  if (ec)
    return base::makeError(base::ErrorCode::kIoError,
                           "cannot write '" + path + "': " + ec.message());
  return base::Ok{};
}

bool endsWith(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

/// Writes the outputs the user asked for.
base::Status writeOutputs(const CliArgs& args, const input::WorldSpec& spec,
                          const analysis::Hydrology& h, int imageSize) {
  std::vector<std::pair<std::string, bool>> outputs; // (path, is image)
  if (auto o = args.get("-o")) {
    if (endsWith(*o, ".png"))
      outputs.emplace_back(*o, true);
    else if (endsWith(*o, ".geojson") || endsWith(*o, ".json"))
      outputs.emplace_back(*o, false);
    else
      return base::makeError(base::ErrorCode::kInvalidInput,
                             "output '" + *o +
                                 "': use a .geojson (river network) or .png "
                                 "(network image) file name");
  }
  if (auto image = args.get("--image"))
    outputs.emplace_back(*image, true);
  for (const auto& [path, isImage] : outputs) {
    if (isImage) {
      STRAHLER_RETURN_IF_ERROR(image::writePng(
          path, render::drawNetworkImage(spec.land, h.network, h.blocks, h.analysis, imageSize)));
    } else {
      STRAHLER_RETURN_IF_ERROR(
          writeTextFile(path, render::riversGeoJson(h.network, h.analysis, spec.projection)));
    }
  }
  return base::Ok{};
}

int fail(const base::Error& error) {
  std::fprintf(stderr, "strahler: error: %s\n", error.message.c_str());
  return 1;
}

} // namespace

const char* generateUsage() noexcept {
  return "usage: strahler generate [--coast FILE.geojson] [--params FILE.json] [--mouths "
         "FILE.geojson]\n"
         "                         [--seed N] [-o OUT.geojson|OUT.png] [--image OUT.png]\n"
         "                         [--image-size PX] [--json] [--quiet]\n"
         "Grows the river network of a coastline (default: the embedded island) and prints a\n"
         "summary. -o writes the river network as GeoJSON (or an image for .png); --image\n"
         "writes a picture of the network over its blocks (PX: 64..8192, default 1600).\n";
}

int runGenerate(const std::vector<std::string>& rawArgs) {
  auto parsed =
      CliArgs::parse("generate", rawArgs,
                     {"--coast", "--params", "--mouths", "--seed", "-o", "--image", "--image-size"},
                     {"--json", "--quiet", "--help", "-h"});
  if (!parsed) {
    std::fprintf(stderr, "strahler: %s\n%s", parsed.error().message.c_str(), generateUsage());
    return 2;
  }
  const CliArgs& args = parsed.value();
  if (args.has("--help") || args.has("-h")) {
    std::fputs(generateUsage(), stdout);
    return 0;
  }
  if (!args.positional().empty()) {
    std::fprintf(stderr, "strahler: unexpected argument '%s'\n%s", args.positional()[0].c_str(),
                 generateUsage());
    return 2;
  }
  auto seed = args.getU64("--seed");
  auto imageSize = args.getInt("--image-size", 64, 8192);
  for (const auto* usageError :
       {seed.ok() ? nullptr : &seed.error(), imageSize.ok() ? nullptr : &imageSize.error()})
    if (usageError) {
      std::fprintf(stderr, "strahler: %s\n%s", usageError->message.c_str(), generateUsage());
      return 2;
    }

  input::WorldSources sources;
  sources.coastPath = args.get("--coast").value_or("");
  sources.paramsPath = args.get("--params").value_or("");
  sources.mouthsPath = args.get("--mouths").value_or("");
  sources.seed = seed.value();

  base::StageTimer timer;
  timer.start("input");
  auto spec = input::loadWorldSpec(sources);
  if (!spec)
    return fail(spec.error());
  timer.finish();
  TerminalProgress progress(args.has("--quiet"));
  auto hydrology = analysis::buildHydrology(spec.value(), progress.callback(), &timer);
  if (!hydrology)
    return fail(hydrology.error());

  timer.start("output");
  if (auto written = writeOutputs(args, spec.value(), hydrology.value(),
                                  static_cast<int>(imageSize.value().value_or(kDefaultImageSize)));
      !written)
    return fail(written.error());
  timer.finish();

  const WorldSummary summary = summarize(spec.value(), hydrology.value(), timer.stages());
  if (!args.has("--quiet") || args.has("--json"))
    std::fputs((args.has("--json") ? toJson(summary) + "\n" : toText(summary)).c_str(), stdout);
  return 0;
}

} // namespace strahler::app
