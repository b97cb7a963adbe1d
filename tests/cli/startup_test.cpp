// The program's start-up (issue 18): OpenImageIO and its ~250 libraries are loaded only by
// what needs them (float TIFF/EXR, image files), through the module strahler_image_oiio.so
// beside the program; without that module those requests fail with a message naming it, and
// everything else works. Speed is measured by scripts/bench/startup.sh, not here.
#include "program_run.h"
#include "serve_process.h"
#include "test_client.h"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace {

namespace fs = std::filesystem;
using strahler::http::test::fetch;
using strahler::http::test::getRequest;
using strahler::test_support::ProcessRun;
using strahler::test_support::runProgram;
using strahler::test_support::ServeProcess;
using namespace std::chrono_literals;

constexpr const char* kModule = "strahler_image_oiio.so";

// Sanitized builds link OpenImageIO at start (core/image/CMakeLists.txt: LeakSanitizer cannot
// read the TLS of libraries that dlopen loads), so its absence is checked in the others only.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kOpenImageIoAtStart = true;
#else
constexpr bool kOpenImageIoAtStart = false;
#endif

fs::path scratchDir() {
  return strahler::test_support::processScratchDir(
      fs::path(STRAHLER_BINARY_DIR) / "cli_test_scratch", "startup");
}

/// Runs `program args` with `environment` ("NAME=value ...", may be empty) before it.
ProcessRun run(const std::string& environment, const std::string& args,
               const std::string& program = STRAHLER_EXECUTABLE) {
  return runProgram(environment + " " + program, args, scratchDir());
}

/// The default island's world file, generated once per test process.
const fs::path& world() {
  static const fs::path path = [] {
    const fs::path file = scratchDir() / "startup.world";
    const ProcessRun generated = run("", "generate --quiet -o " + file.string());
    EXPECT_EQ(generated.exitCode, 0) << generated.err;
    return file;
  }();
  return path;
}

/// `strahler tile` of the world's local tile 2/1/2 in `format`, 32 pixels a side, into `out`.
std::string tileArgs(const std::string& format, const fs::path& out) {
  return "tile " + world().string() + " --scheme local --z 2 --x 1 --y 2 --format " + format +
         " --size 32 -o " + out.string();
}

/// The shared objects the dynamic loader reported loading (LD_DEBUG=files), one per line.
std::vector<std::string> loadedObjects(const std::string& ldDebugOutput) {
  std::vector<std::string> objects;
  std::istringstream lines(ldDebugOutput);
  for (std::string line; std::getline(lines, line);) {
    const std::size_t file = line.find("file=");
    if (file != std::string::npos && line.find("[0];") != std::string::npos &&
        (line.find("needed by") != std::string::npos ||
         line.find("dynamically loaded") != std::string::npos))
      objects.push_back(line.substr(file + 5, line.find(' ', file) - file - 5));
  }
  return objects;
}

std::string joined(const std::vector<std::string>& items) {
  std::string out;
  for (const std::string& item : items)
    out += item + " ";
  return out;
}

bool mentionsOpenImageIo(const std::string& text) {
  return text.find("OpenImageIO") != std::string::npos || text.find(kModule) != std::string::npos;
}

/// The memory map of process `pid`.
std::string mapsOf(pid_t pid) {
  return strahler::test_support::readWholeFile("/proc/" + std::to_string(pid) + "/maps");
}

TEST(Startup, HelpInfoAndIntegerAndMeshTilesNeverLoadOpenImageIo) {
  // Few libraries in all: libstdc++, libm, libgcc_s, libc, zlib, libspng, Draco, protobuf-lite,
  // GMP. A bound, not the list, so that a Debian point release does not break the test; the
  // 264 of OpenImageIO's closure are far beyond it.
  constexpr std::size_t kMaxLibraries = 20;
  if (kOpenImageIoAtStart)
    GTEST_SKIP() << "this sanitized build links OpenImageIO at start";
  std::vector<std::string> commands = {"--help", "info " + world().string()};
  for (const char* format : {"png", "terrarium", "png16", "drc", "glb"})
    commands.push_back(tileArgs(format, scratchDir() / (std::string("t.") + format)));
  for (const std::string& args : commands) {
    const ProcessRun r = run("LD_DEBUG=files", args);
    ASSERT_EQ(r.exitCode, 0) << args << "\n" << r.err;
    const std::vector<std::string> objects = loadedObjects(r.err);
    EXPECT_FALSE(mentionsOpenImageIo(joined(objects))) << args << " loaded " << joined(objects);
    EXPECT_LE(objects.size(), kMaxLibraries) << args << " loaded " << joined(objects);
    EXPECT_GE(objects.size(), 4u) << "LD_DEBUG=files reported nothing: " << r.err.substr(0, 500);
  }
}

TEST(Startup, FloatTilesLoadTheModuleAndItsOpenImageIo) {
  // The other side of the test above: the same check sees the module when it is loaded.
  for (const auto& [format, magic] :
       {std::pair<std::string, std::string>{"exr", "v/1\x01"}, {"tif", "II*"}}) {
    const fs::path out = scratchDir() / ("float." + format);
    const ProcessRun r = run("LD_DEBUG=files", tileArgs(format, out));
    ASSERT_EQ(r.exitCode, 0) << r.err.substr(r.err.size() > 2000 ? r.err.size() - 2000 : 0);
    const std::string objects = joined(loadedObjects(r.err));
    EXPECT_NE(objects.find(kModule), std::string::npos) << objects;
    EXPECT_NE(objects.find("libOpenImageIO.so"), std::string::npos) << objects;
    EXPECT_EQ(strahler::test_support::readWholeFile(out).substr(0, magic.size()), magic) << format;
  }
}

TEST(Startup, ServeMapsOpenImageIoOnlyOnceAFloatTileIsAskedFor) {
  ServeProcess serve({STRAHLER_EXECUTABLE, "serve", world().string(), "--quiet", "--port", "0",
                      "--threads", "1", "--workers", "1", "--cache-dir",
                      (scratchDir() / "serve-cache").string()},
                     "STRAHLER_STARTUP_TEST=1");
  ASSERT_GT(serve.pid(), 0);
  std::string banner;
  const std::uint16_t port = serve.readPort(&banner);
  ASSERT_NE(port, 0) << banner;
  for (const char* target : {"/worlds/startup/local/2/1/2.png", "/worlds/startup/local/2/1/2.drc",
                             "/worlds/startup/local/2/1/2.png16"}) {
    const auto tile = fetch(port, getRequest(target), 30s);
    ASSERT_TRUE(tile && tile->status == 200) << target;
  }
  if (!kOpenImageIoAtStart) {
    EXPECT_FALSE(mentionsOpenImageIo(mapsOf(serve.pid())));
  }
  const auto exr = fetch(port, getRequest("/worlds/startup/local/2/1/2.exr?size=32"), 60s);
  ASSERT_TRUE(exr);
  EXPECT_EQ(exr->status, 200) << exr->body;
  EXPECT_EQ(exr->body.substr(0, 4), "v/1\x01");
  const std::string maps = mapsOf(serve.pid());
  EXPECT_NE(maps.find(kModule), std::string::npos);
  EXPECT_NE(maps.find("libOpenImageIO.so"), std::string::npos);
}

TEST(Startup, WithoutTheModuleFloatTilesFailWithItsNameAndTheRestWorks) {
  const fs::path empty = scratchDir() / "no-module";
  fs::create_directories(empty);
  const std::string environment = "STRAHLER_MODULE_DIR=" + empty.string();
  const ProcessRun exr = run(environment, tileArgs("exr", scratchDir() / "missing.exr"));
  EXPECT_EQ(exr.exitCode, 1);
  EXPECT_NE(exr.err.find("strahler: error: float EXR: the OpenImageIO module "
                         "strahler_image_oiio.so is not in " +
                         empty.string()),
            std::string::npos)
      << exr.err;
  const ProcessRun png = run(environment, tileArgs("png", scratchDir() / "present.png"));
  EXPECT_EQ(png.exitCode, 0) << png.err;

  ServeProcess serve({STRAHLER_EXECUTABLE, "serve", world().string(), "--quiet", "--port", "0",
                      "--threads", "1", "--workers", "1", "--cache-dir",
                      (scratchDir() / "serve-cache-2").string()},
                     environment);
  ASSERT_GT(serve.pid(), 0);
  std::string banner;
  const std::uint16_t port = serve.readPort(&banner);
  ASSERT_NE(port, 0) << banner;
  for (int attempt = 0; attempt < 2; ++attempt) { // the failure is not cached as a tile
    const auto tif = fetch(port, getRequest("/worlds/startup/local/2/1/2.tif"), 30s);
    ASSERT_TRUE(tif);
    EXPECT_EQ(tif->status, 501);
    EXPECT_NE(tif->body.find("float TIFF: the OpenImageIO module strahler_image_oiio.so is not in"),
              std::string::npos)
        << tif->body;
  }
  const auto pngTile = fetch(port, getRequest("/worlds/startup/local/2/1/2.png"), 30s);
  ASSERT_TRUE(pngTile);
  EXPECT_EQ(pngTile->status, 200);
  const auto health = fetch(port, getRequest("/health"), 10s);
  ASSERT_TRUE(health);
  EXPECT_EQ(health->status, 200);
}

TEST(Startup, ABrokenModuleIsNamedInTheError) {
  const fs::path folder = scratchDir() / "broken-module";
  fs::create_directories(folder);
  std::ofstream(folder / kModule) << "not a shared object";
  const ProcessRun r =
      run("STRAHLER_MODULE_DIR=" + folder.string(), tileArgs("tif", scratchDir() / "b.tif"));
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("cannot load the OpenImageIO module: " + (folder / kModule).string()),
            std::string::npos)
      << r.err;
}

TEST(Startup, TheInstalledProgramFindsItsModule) {
  // `cmake --install` puts the program in bin/ and the module in lib/strahler/ (or the
  // platform's lib folder), and removes the build tree's RUNPATH: the program finds the module
  // relative to itself.
  const fs::path prefix = scratchDir() / "prefix";
  fs::remove_all(prefix);
  const ProcessRun install =
      run("", "--install " + std::string(STRAHLER_BINARY_DIR) + " --prefix " + prefix.string(),
          STRAHLER_CMAKE_COMMAND);
  ASSERT_EQ(install.exitCode, 0) << install.out << install.err;
  const fs::path program = prefix / "bin" / "strahler";
  ASSERT_TRUE(fs::exists(program)) << install.out;
  const fs::path out = scratchDir() / "installed.exr";
  const ProcessRun r = run("", tileArgs("exr", out), program.string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(strahler::test_support::readWholeFile(out).substr(0, 4), "v/1\x01");
  // And not by chance through the build tree: the module it loaded is the installed one.
  const ProcessRun traced = run("LD_DEBUG=files", tileArgs("exr", out), program.string());
  const std::string objects = joined(loadedObjects(traced.err));
  EXPECT_NE(objects.find(prefix.string()), std::string::npos) << objects;
  EXPECT_EQ(objects.find(std::string(STRAHLER_BINARY_DIR) + "/bin"), std::string::npos) << objects;
}

} // namespace
