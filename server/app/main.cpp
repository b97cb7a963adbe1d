// strahler: procedural river networks and terrain (Génevaux et al. 2013), served as tiles.
#include "cli_args.h"
#include "command_support.h"
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
    "  tile       write one tile of a world file (heightmap, mesh, terrain, vector or layer)\n"
    "  export     write a world's tiles to a PMTiles or MBTiles archive (static hosting)\n"
    "  export-heightmap  write a 16-bit heightmap of a box for Unity, Unreal or Godot\n"
    "  serve      serve worlds over HTTP (viewer, TileJSON, tiles, metrics)\n"
    "  help       show this text; 'strahler help <command>' shows a command's options\n"
    "  version    print the version and the terrain generator's version\n";

using Run = int (*)(const std::vector<std::string>&);

struct Command {
  const char* name;
  Run run;
};

constexpr Command kCommands[] = {
    {"generate", strahler::app::runGenerate},
    {"info", strahler::app::runInfo},
    {"render", strahler::app::runRender},
    {"analyze", strahler::app::runAnalyze},
    {"tile", strahler::app::runTile},
    {"export", strahler::app::runExport},
    {"export-heightmap", strahler::app::runExportHeightmap},
    {"serve", strahler::app::runServe},
};

Run findCommand(const std::string& name) {
  for (const Command& command : kCommands)
    if (name == command.name)
      return command.run;
  return nullptr;
}

/// "unknown command 'x'", with the nearest command name when one is close.
int unknownCommand(const std::string& name) {
  std::vector<std::string> names = {"help", "version"};
  for (const Command& command : kCommands)
    names.emplace_back(command.name);
  const std::string guess = strahler::app::closestName(name, names);
  return strahler::app::usageError(
      {strahler::base::ErrorCode::kInvalidInput,
       "unknown command '" + name + "'" + (guess.empty() ? "" : "; did you mean '" + guess + "'?")},
      "");
}

} // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> all(argv + 1, argv + argc);
  if (all.empty()) {
    std::fputs(kUsage, stderr);
    return 2;
  }
  const std::string& command = all.front();
  const std::vector<std::string> rest(all.begin() + 1, all.end());
  if (const Run run = findCommand(command))
    return run(rest);
  if (command == "help" || command == "--help" || command == "-h") {
    if (rest.empty()) {
      std::fputs(kUsage, stdout);
      return 0;
    }
    if (const Run run = findCommand(rest.front()))
      return run({"--help"});
    return unknownCommand(rest.front());
  }
  if (command == "version" || command == "--version") {
    // The generator version names the terrain a world file holds (and keys the world cache).
    std::printf("strahler %s\ngenerator %s\n", STRAHLER_VERSION,
                strahler::construction::kGeneratorVersion);
    return 0;
  }
  return unknownCommand(command);
}
