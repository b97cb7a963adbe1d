// One error style for every command: "strahler: error: ..." on one line, then where the help
// is, never the help itself; "did you mean" for options and commands; exit 2 for a wrong
// command line and 1 for a wrong file; a GeoJSON named where a world file belongs is called
// GeoJSON. And every command's --help: within 100 columns, its synopsis as docs/cli.md has it.
#include "program_run.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using strahler::test_support::ProcessRun;
using strahler::test_support::readWholeFile;

fs::path scratchDir() {
  return strahler::test_support::processScratchDir(
      fs::path(STRAHLER_BINARY_DIR) / "cli_test_scratch", "cli-errors");
}

ProcessRun strahler(const std::string& args) {
  return strahler::test_support::runProgram(STRAHLER_EXECUTABLE, args, scratchDir());
}

const std::vector<std::string> kCommands = {"generate", "info",   "render",           "analyze",
                                            "tile",     "export", "export-heightmap", "serve"};

std::string mallorca() {
  return std::string(STRAHLER_TEST_DATA_DIR) + "/mallorca.geojson";
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    out.push_back(line);
  return out;
}

/// Characters, not bytes: the help texts hold "×" and "…".
std::size_t columns(const std::string& line) {
  std::size_t n = 0;
  for (const char c : line)
    n += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
  return n;
}

/// The synopsis of a help text: its "usage:" lines and their indented continuations.
std::string synopsis(const std::string& help) {
  std::string out;
  for (const std::string& line : lines(help)) {
    if (line.rfind("usage:", 0) != 0 && line.rfind(" ", 0) != 0)
      break;
    out += line + "\n";
  }
  return out;
}

/// A wrong command line: exit 2, the error on one line and where the help is on the next.
void expectUsageError(const std::string& args, const std::string& error,
                      const std::string& command) {
  const ProcessRun run = strahler(args);
  EXPECT_EQ(run.exitCode, 2) << args << ": " << run.err;
  EXPECT_EQ(run.err, "strahler: error: " + error + "\nsee 'strahler " +
                         (command.empty() ? "" : command + " ") + "--help'\n")
      << args;
  EXPECT_TRUE(run.out.empty()) << args;
}

TEST(CliHelp, EveryCommandsHelpFitsInOneHundredColumnsAndItsSynopsisIsInDocsCli) {
  const std::string docs = readWholeFile(fs::path(STRAHLER_SOURCE_DIR) / "docs/cli.md");
  ASSERT_FALSE(docs.empty());
  for (const std::string& command : kCommands) {
    const ProcessRun help = strahler(command + " --help");
    EXPECT_EQ(help.exitCode, 0) << command;
    EXPECT_TRUE(help.err.empty()) << command << ": " << help.err;
    for (const std::string& line : lines(help.out))
      EXPECT_LE(columns(line), 100u) << command << ": " << line;
    const std::string shown = synopsis(help.out);
    ASSERT_FALSE(shown.empty()) << command;
    EXPECT_NE(docs.find("```\n" + shown + "```"), std::string::npos)
        << "docs/cli.md lacks the synopsis of " << command << ":\n"
        << shown;
    // `strahler help CMD` is `strahler CMD --help`.
    const ProcessRun viaHelp = strahler("help " + command);
    EXPECT_EQ(viaHelp.exitCode, 0) << command;
    EXPECT_EQ(viaHelp.out, help.out) << command;
  }
  const ProcessRun top = strahler("--help");
  EXPECT_EQ(top.exitCode, 0);
  for (const std::string& line : lines(top.out))
    EXPECT_LE(columns(line), 100u) << line;
  for (const std::string& command : kCommands)
    EXPECT_NE(top.out.find("  " + command + " "), std::string::npos) << command;
}

TEST(CliErrors, AnUnknownOptionIsOneLineAndThePlaceOfTheHelpInEveryCommand) {
  for (const std::string& command : kCommands)
    expectUsageError(command + " --bogus-option",
                     "unknown option '--bogus-option' for '" + command + "'", command);
}

TEST(CliErrors, MisspelledOptionsAndCommandsGetADidYouMean) {
  expectUsageError("generate --coastline " + mallorca(),
                   "unknown option '--coastline' for 'generate'; did you mean '--coast'?",
                   "generate");
  expectUsageError("serve --prot 8080",
                   "unknown option '--prot' for 'serve'; did you mean '--port'?", "serve");
  expectUsageError("export-heightmap w.world --engin unity -o h.r16",
                   "unknown option '--engin' for 'export-heightmap'; did you mean '--engine'?",
                   "export-heightmap");
  expectUsageError("tile w.world --fromat png",
                   "unknown option '--fromat' for 'tile'; did you mean '--format'?", "tile");
  expectUsageError("generat", "unknown command 'generat'; did you mean 'generate'?", "");
  expectUsageError("help sever", "unknown command 'sever'; did you mean 'serve'?", "");
  expectUsageError("transmogrify", "unknown command 'transmogrify'", "");
}

TEST(CliErrors, AWrongValueIsAWrongCommandLineInEveryCommand) {
  const fs::path world = scratchDir() / "absent.world"; // never read: the line is refused first
  expectUsageError("render " + world.string() + " --size 10 -o x.png",
                   "option '--size' must be an integer in [64, 8192], got '10'", "render");
  expectUsageError("generate --grower lsystem",
                   "unknown grower 'lsystem': expected \"grammar\" (the paper's open grammar) or "
                   "\"dla\" (diffusion-limited aggregation)",
                   "generate");
  expectUsageError("generate -o out.txt",
                   "output 'out.txt': use a .world (world file), .geojson (river network) or .png "
                   "(network image) file name",
                   "generate");
  expectUsageError("generate " + mallorca(),
                   "unexpected argument '" + mallorca() + "'; a coastline is given with --coast " +
                       mallorca(),
                   "generate");
  expectUsageError("serve --seed x", "option '--seed' must be an integer in [0, 2^64 - 1], got 'x'",
                   "serve");
  expectUsageError("export-heightmap " + world.string() + " --engine cryengine -o h.r16",
                   "--engine cryengine: use unity, unreal, godot or raw", "export-heightmap");
  expectUsageError("info", "expected a WORLD file", "info");
}

TEST(CliErrors, AGeoJsonWhereAWorldBelongsIsNamedAsSuch) {
  const std::string geojson = mallorca();
  const std::string make =
      "make its world first with 'strahler generate --coast " + geojson + " -o mallorca.world'";
  const struct {
    std::string args;
    std::string hint;
  } cases[] = {
      {"info " + geojson, make},
      {"render " + geojson + " -o x.png", make},
      {"analyze " + geojson, make},
      {"tile " + geojson + " --z 0 --x 0 --y 0 --format png -o x.png", make},
      {"export " + geojson + " --zooms 0-1 -o " + (scratchDir() / "x.pmtiles").string(), make},
      {"export-heightmap " + geojson + " --engine unity -o " + (scratchDir() / "h.r16").string(),
       make},
      {"serve --port 0 " + geojson,
       "serve a coastline with 'strahler serve --coast " + geojson + "'"},
  };
  for (const auto& c : cases) {
    const ProcessRun run = strahler(c.args);
    EXPECT_EQ(run.exitCode, 1) << c.args << ": " << run.err;
    EXPECT_NE(run.err.find("strahler: error: '" + geojson +
                           "' is GeoJSON, not a world file: " + c.hint + "\n"),
              std::string::npos)
        << c.args << ": " << run.err;
    EXPECT_EQ(run.err.find("usage:"), std::string::npos) << c.args;
  }
}

} // namespace
