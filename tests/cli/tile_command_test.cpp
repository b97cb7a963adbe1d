// `strahler tile`: every format with its magic bytes and the refusals of a tile outside the
// grid or of a bad size, format or scheme; `--layer NAME` (issue 28) as the server's
// layers/{name}/ serves it, and its refusals (an unknown layer, a parameter the layer does
// not take, --format and --layer together, a layer in the Cesium pyramid).
#include "program_run.h"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <string>

namespace {

namespace fs = std::filesystem;
using strahler::test_support::ProcessRun;
using strahler::test_support::runProgram;

fs::path scratchDir() {
  return strahler::test_support::processScratchDir(
      fs::path(STRAHLER_BINARY_DIR) / "cli_test_scratch", "tile-command");
}

ProcessRun run(const std::string& args) {
  return runProgram(STRAHLER_EXECUTABLE, args, scratchDir());
}

/// The default island's world file, generated once per test process.
const fs::path& world() {
  static const fs::path path = [] {
    const fs::path file = scratchDir() / "island.world";
    const ProcessRun generated = run("generate --quiet -o " + file.string());
    EXPECT_EQ(generated.exitCode, 0) << generated.err;
    return file;
  }();
  return path;
}

std::string tileArgs(const std::string& rest, const fs::path& out) {
  return "tile " + world().string() + " --scheme web --z 12 --x 1736 --y 1494 " + rest + " -o " +
         out.string();
}

/// Bit depth and colour type from a PNG's IHDR (0s if not a PNG).
std::pair<int, int> depthAndColour(const std::string& png) {
  if (png.size() < 33 || png.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0)
    return {0, 0};
  return {static_cast<unsigned char>(png[24]), static_cast<unsigned char>(png[25])};
}

TEST(TileCommand, WritesLayerTilesAsGreyPngs) {
  const fs::path slope = scratchDir() / "slope.png", bush = scratchDir() / "bush.png",
                 shade = scratchDir() / "shade.png";
  const ProcessRun a = run(tileArgs("--layer slope", slope));
  ASSERT_EQ(a.exitCode, 0) << a.err;
  EXPECT_EQ(depthAndColour(strahler::test_support::readWholeFile(slope)), std::make_pair(16, 0));
  const ProcessRun b = run(tileArgs("--layer vegetation --species bush --size 64", bush));
  ASSERT_EQ(b.exitCode, 0) << b.err;
  EXPECT_EQ(depthAndColour(strahler::test_support::readWholeFile(bush)), std::make_pair(8, 0));
  const ProcessRun c = run(tileArgs("--layer hillshade --azimuth 270 --altitude 30", shade));
  ASSERT_EQ(c.exitCode, 0) << c.err;
  EXPECT_EQ(depthAndColour(strahler::test_support::readWholeFile(shade)), std::make_pair(8, 0));
}

TEST(TileCommand, RefusesBadLayerRequestsNamingTheProblem) {
  const fs::path out = scratchDir() / "bad.png";
  const std::pair<std::string, std::string> cases[] = {
      {"--layer snow", "unknown layer 'snow'"},
      {"--layer slope --azimuth 90", "hillshade layer only"},
      {"--layer hillshade --azimuth 360", "azimuth must be in [0, 360)"},
      {"--layer vegetation --species oak", "unknown species 'oak'"},
      {"--format png --layer slope", "give --format or --layer"},
      {"--format png --species tree", "--species needs --layer"},
      {"", "give --format or --layer"},
  };
  for (const auto& [args, message] : cases) {
    const ProcessRun r = run(tileArgs(args, out));
    EXPECT_NE(r.exitCode, 0) << args;
    EXPECT_NE(r.err.find(message), std::string::npos) << args << ": " << r.err;
  }
  const ProcessRun cesium =
      run("tile " + world().string() + " --scheme cesium --z 2 --x 1 --y 1 --layer slope -o " +
          out.string());
  EXPECT_NE(cesium.exitCode, 0);
  EXPECT_NE(cesium.err.find("--layer goes with --scheme web or local"), std::string::npos)
      << cesium.err;
}

TEST(TileCommand, WritesVegetationTilesAsTheServerDoes) {
  const fs::path trees = scratchDir() / "trees.json", shallow = scratchDir() / "shallow.json";
  const ProcessRun r =
      run("tile " + world().string() +
          " --scheme web --z 16 --x 27784 --y 23912 --format json -o " + trees.string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::string json = strahler::test_support::readWholeFile(trees);
  EXPECT_EQ(json.rfind("{\"tile\":[16,27784,23912],\"species\":[", 0), 0u) << json.substr(0, 80);
  EXPECT_NE(json.find("\"instances\":["), std::string::npos);
  const ProcessRun z12 = run(tileArgs("--format json", shallow));
  EXPECT_NE(z12.exitCode, 0);
  EXPECT_NE(z12.err.find("zooms 16 to 18"), std::string::npos) << z12.err;
}

TEST(TileCommand, WritesEveryFormatAndRejectsBadRequests) {
  const std::string base = "tile " + world().string() + " ";
  const std::pair<const char*, const char*> formats[] = {
      {"png", "\x89PNG"}, {"terrarium", "\x89PNG"}, {"png16", "\x89PNG"}, {"tif", "II*"},
      {"exr", "v/1\x01"}, {"drc", "DRACO"},         {"glb", "glTF"},      {"relief", "\x89PNG"}};
  for (const auto& [format, magic] : formats) {
    const fs::path out = scratchDir() / (std::string("t.") + format);
    const ProcessRun tile = run(base + "--scheme local --z 2 --x 1 --y 2 --format " + format +
                                " --size 32 -o " + out.string());
    ASSERT_EQ(tile.exitCode, 0) << format << ": " << tile.err;
    EXPECT_EQ(strahler::test_support::readWholeFile(out).substr(0, std::strlen(magic)), magic)
        << format;
  }
  const ProcessRun outside = run(base + "--z 3 --x 8 --y 0 --format png -o x.png");
  EXPECT_EQ(outside.exitCode, 1);
  EXPECT_NE(outside.err.find("outside the grid"), std::string::npos) << outside.err;
  const ProcessRun deep = run(base + "--z 19 --x 0 --y 0 --format png -o x.png");
  EXPECT_EQ(deep.exitCode, 1);
  const ProcessRun size = run(base + "--z 1 --x 0 --y 0 --format png --size 4096 -o x.png");
  EXPECT_EQ(size.exitCode, 2); // a wrong command line, as render's --size
  EXPECT_NE(size.err.find("option '--size' must be an integer in [16, 1024] for png tiles, got "
                          "'4096'"),
            std::string::npos)
      << size.err;
  const ProcessRun format = run(base + "--z 1 --x 0 --y 0 --format bmp -o x.bmp");
  EXPECT_EQ(format.exitCode, 2);
  EXPECT_NE(format.err.find("unknown tile format 'bmp'"), std::string::npos) << format.err;
  const ProcessRun scheme = run(base + "--scheme polar --z 1 --x 0 --y 0 --format png -o x.png");
  EXPECT_EQ(scheme.exitCode, 2);
}

} // namespace
