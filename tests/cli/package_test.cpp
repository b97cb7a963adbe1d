// Packaging (issue 18): CPack's Debian package holds the program, its OpenImageIO module, the
// built viewer and the manual page; unpacked anywhere, the program finds the module and the
// viewer relative to itself, whatever the current directory. dpkg-deb reads the package.
#include "program_run.h"
#include "serve_process.h"
#include "test_client.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

namespace fs = std::filesystem;
using strahler::http::test::fetch;
using strahler::http::test::getRequest;
using strahler::test_support::ProcessRun;
using strahler::test_support::readWholeFile;
using strahler::test_support::ServeProcess;
using namespace std::chrono_literals;

fs::path scratchDir() {
  return strahler::test_support::processScratchDir(
      fs::path(STRAHLER_BINARY_DIR) / "cli_test_scratch", "package");
}

/// Runs a shell command line (its standard error kept in the result).
ProcessRun shell(const std::string& command) {
  return strahler::test_support::runProgram("", command + " 2>&1", scratchDir());
}

/// The package CPack writes from this build tree, made once per test process.
const fs::path& package() {
  static const fs::path file = [] {
    const fs::path out = scratchDir() / "cpack";
    fs::remove_all(out);
    const ProcessRun made =
        shell(std::string(STRAHLER_CPACK_COMMAND) + " -G DEB -B " + out.string() + " --config " +
              STRAHLER_BINARY_DIR + "/CPackConfig.cmake");
    EXPECT_EQ(made.exitCode, 0) << made.out;
    for (const auto& entry : fs::directory_iterator(out))
      if (entry.path().extension() == ".deb")
        return entry.path();
    ADD_FAILURE() << "no .deb in " << out << ": " << made.out;
    return fs::path();
  }();
  return file;
}

TEST(Package, TheDebianPackageHoldsProgramModuleViewerAndManualPage) {
  ASSERT_FALSE(package().empty());
  const ProcessRun fields = shell("dpkg-deb -f " + package().string() + " Package Version Depends");
  ASSERT_EQ(fields.exitCode, 0) << fields.out;
  EXPECT_NE(fields.out.find("Package: strahler\n"), std::string::npos) << fields.out;
  EXPECT_NE(fields.out.find("Version: " STRAHLER_PROJECT_VERSION "\n"), std::string::npos)
      << fields.out;
  // dpkg-shlibdeps found the libraries the program and its module link.
  for (const char* library : {"libc6", "libstdc++6", "libprotobuf", "libopenimageio"})
    EXPECT_NE(fields.out.find(library), std::string::npos) << library << " in " << fields.out;
  const ProcessRun listing = shell("dpkg-deb -c " + package().string());
  ASSERT_EQ(listing.exitCode, 0) << listing.out;
  for (const char* path :
       {"./usr/bin/strahler", "./usr/lib/strahler/strahler_image_oiio.so",
        "./usr/share/strahler/web/index.html", "./usr/share/strahler/web/game.html",
        "./usr/share/strahler/web/src/viewer.js", "./usr/share/man/man1/strahler.1"})
    EXPECT_NE(listing.out.find(std::string(path) + "\n"), std::string::npos) << path;
}

TEST(Package, TheUnpackedProgramFindsItsViewerAndModuleFromAnyDirectory) {
  ASSERT_FALSE(package().empty());
  const fs::path root = scratchDir() / "unpacked";
  fs::remove_all(root);
  const ProcessRun unpacked = shell("dpkg-deb -x " + package().string() + " " + root.string());
  ASSERT_EQ(unpacked.exitCode, 0) << unpacked.out;
  const std::string program = (root / "usr/bin/strahler").string();

  // --version names the generator whose terrain the program writes into world files.
  const ProcessRun version = shell("cd / && " + program + " --version");
  EXPECT_EQ(version.exitCode, 0);
  const fs::path world = scratchDir() / "packaged.world";
  const ProcessRun generated = shell(program + " generate --quiet -o " + world.string() +
                                     " --cache-dir " + (scratchDir() / "cache").string());
  ASSERT_EQ(generated.exitCode, 0) << generated.out;
  const ProcessRun info = shell(program + " info " + world.string());
  ASSERT_EQ(info.exitCode, 0) << info.out;
  const std::string generator = nlohmann::json::parse(info.out).at("generatorVersion");
  EXPECT_EQ(version.out, "strahler " STRAHLER_PROJECT_VERSION "\ngenerator " + generator + "\n");

  // The manual page documents every command the program lists.
  const std::string manual = readWholeFile(root / "usr/share/man/man1/strahler.1");
  const ProcessRun help = shell(program + " --help");
  for (const char* command : {"generate", "info", "render", "analyze", "tile", "serve"}) {
    ASSERT_NE(help.out.find(std::string("  ") + command + " "), std::string::npos) << command;
    EXPECT_NE(manual.find(std::string(".SS ") + command + "\n"), std::string::npos) << command;
  }

  // serve started from / (not the source tree): the viewer is the packaged one (marked here so
  // that the build tree's web/dist, the same bytes, cannot pass for it), and a float tile loads
  // the packaged OpenImageIO module.
  const fs::path packagedIndex = root / "usr/share/strahler/web/index.html";
  std::ofstream(packagedIndex, std::ios::app) << "<!-- unpacked by package_test -->\n";
  ServeProcess serve({"/bin/sh", "-c",
                      "cd / && exec " + program +
                          " serve --quiet --port 0 --threads 1 --cache-dir " +
                          (scratchDir() / "cache").string()},
                     "");
  ASSERT_GT(serve.pid(), 0);
  std::string banner;
  const std::uint16_t port = serve.readPort(&banner);
  ASSERT_NE(port, 0) << banner;
  const auto index = fetch(port, getRequest("/"), 30s);
  ASSERT_TRUE(index && index->status == 200);
  EXPECT_EQ(index->body, readWholeFile(packagedIndex));
  EXPECT_NE(index->body.find("unpacked by package_test"), std::string::npos);
  const auto script = fetch(port, getRequest("/src/viewer.js"), 30s);
  ASSERT_TRUE(script && script->status == 200);
  EXPECT_EQ(script->body, readWholeFile(root / "usr/share/strahler/web/src/viewer.js"));
  const auto tif = fetch(port, getRequest("/worlds/default/local/1/0/1.tif?size=16"), 60s);
  ASSERT_TRUE(tif);
  EXPECT_EQ(tif->status, 200) << tif->body;
}

} // namespace
