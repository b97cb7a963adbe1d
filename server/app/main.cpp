// strahler: procedural river networks and terrain (Génevaux et al. 2013), served as tiles.
#include "export_command.h"
#include "generate_command.h"
#include "heightmap_export_command.h"
#include "serve_command.h"
#include "world_commands.h"

#include "strahler/construction/world_builder.h"

#include <cstdio>
#include <string>
#include <vector>

namespace {

constexpr const char* kUsage =
    "usage: strahler <command> [options]\n"
    "commands:\n"
    "  generate   generate (or load from the cache) the world of a coastline\n"
    "  info       print the statistics of a world file as JSON\n"
    "  render     draw a shaded-relief overview of a world file\n"
    "  analyze    check drainage and river profiles of a world file (JSON)\n"
    "  tile       write one heightmap or mesh tile of a world file\n"
    "  export     write a world's tiles to a PMTiles or MBTiles archive (static hosting)\n"
    "  export-heightmap  write a 16-bit heightmap of a box for Unity, Unreal or Godot\n"
    "  serve      serve worlds over HTTP (viewer, TileJSON, tiles, metrics)\n"
    "  help       show this text (strahler <command> --help for a command's options)\n"
    "  version    print the version and the terrain generator's version\n";

} // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> all(argv + 1, argv + argc);
  if (all.empty()) {
    std::fputs(kUsage, stderr);
    return 2;
  }
  const std::string& command = all.front();
  const std::vector<std::string> rest(all.begin() + 1, all.end());
  if (command == "generate")
    return strahler::app::runGenerate(rest);
  if (command == "info")
    return strahler::app::runInfo(rest);
  if (command == "render")
    return strahler::app::runRender(rest);
  if (command == "analyze")
    return strahler::app::runAnalyze(rest);
  if (command == "tile")
    return strahler::app::runTile(rest);
  if (command == "export")
    return strahler::app::runExport(rest);
  if (command == "export-heightmap")
    return strahler::app::runExportHeightmap(rest);
  if (command == "serve")
    return strahler::app::runServe(rest);
  if (command == "help" || command == "--help" || command == "-h") {
    std::fputs(kUsage, stdout);
    return 0;
  }
  if (command == "version" || command == "--version") {
    // The generator version names the terrain a world file holds (and keys the world cache).
    std::printf("strahler %s\ngenerator %s\n", STRAHLER_VERSION,
                strahler::construction::kGeneratorVersion);
    return 0;
  }
  std::fprintf(stderr, "strahler: unknown command '%s'\n%s", command.c_str(), kUsage);
  return 2;
}
