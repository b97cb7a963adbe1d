#pragma once
// What the export-heightmap tests share: the program run in a scratch folder, the default
// island generated once per test process, interrupting a run, and independent readers of the files
// (r16 bytes, libspng, nlohmann::json).
#include "program_run.h"
#include "serve_process.h"

#include "strahler/construction/world.h"
#include "strahler/store/world_file.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <csignal>
#include <cstdint>
#include <filesystem>
#include <spng.h>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <vector>

namespace strahler::test_support::heightmap_export {

namespace fs = std::filesystem;

inline fs::path scratchDir() {
  return strahler::test_support::processScratchDir(
      fs::path(STRAHLER_BINARY_DIR) / "cli_test_scratch", "export-heightmap");
}

/// Runs the strahler program with `args` in the scratch folder.
inline ProcessRun runStrahler(const std::string& args) {
  return strahler::test_support::runProgram(STRAHLER_EXECUTABLE, args, scratchDir());
}

/// The default island as a world file, generated once per test process.
inline const fs::path& islandWorld() {
  static const fs::path path = [] {
    const fs::path p = scratchDir() / "island.world";
    const ProcessRun run = runStrahler("generate --quiet -o " + p.string());
    EXPECT_EQ(run.exitCode, 0) << run.err;
    return p;
  }();
  return path;
}

/// An empty folder of its own for one test's outputs.
inline fs::path outputDir(const std::string& name) {
  const fs::path dir = scratchDir() / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

/// Whether `file` appears within 120 s (polled every 5 ms).
inline bool appearsSoon(const fs::path& file) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (!fs::exists(file) && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  return fs::exists(file);
}

/// Sends `signal` to the export `run`, and expects it to die by that signal within 30 s
/// leaving `dir` empty.
inline void expectInterruptedLeavingNothing(ServeProcess& run, int signal, const fs::path& dir) {
  ::kill(run.pid(), signal);
  const auto status = run.waitUntil(std::chrono::steady_clock::now() + std::chrono::seconds(30));
  ASSERT_TRUE(status) << "export still running 30 s after the signal";
  EXPECT_TRUE(WIFSIGNALED(*status) && WTERMSIG(*status) == signal) << "wait status " << *status;
  EXPECT_TRUE(fs::is_empty(dir)) << "left behind after the signal";
}

/// 16-bit samples of an r16 file read as little-endian bytes, whatever the host's order.
inline std::vector<std::uint16_t> readR16(const fs::path& file) {
  const std::string bytes = readWholeFile(file);
  std::vector<std::uint16_t> values(bytes.size() / 2);
  for (std::size_t i = 0; i < values.size(); ++i)
    values[i] = static_cast<std::uint16_t>(static_cast<unsigned char>(bytes[2 * i]) |
                                           static_cast<unsigned char>(bytes[2 * i + 1]) << 8);
  return values;
}

/// A 16-bit grey PNG decoded by libspng into host-order samples; sets width and height.
inline std::vector<std::uint16_t> readPng16(const fs::path& file, int& width, int& height) {
  const std::string bytes = readWholeFile(file);
  spng_ctx* ctx = spng_ctx_new(0);
  spng_set_png_buffer(ctx, bytes.data(), bytes.size());
  spng_ihdr ihdr{};
  EXPECT_EQ(spng_get_ihdr(ctx, &ihdr), 0);
  EXPECT_EQ(ihdr.bit_depth, 16);
  EXPECT_EQ(ihdr.color_type, SPNG_COLOR_TYPE_GRAYSCALE);
  width = static_cast<int>(ihdr.width), height = static_cast<int>(ihdr.height);
  std::vector<std::uint16_t> values(static_cast<std::size_t>(width) * height);
  // SPNG_FMT_RAW keeps the file's big-endian order (SPNG_FMT_PNG is host-endian): swap here.
  std::vector<unsigned char> raw(values.size() * 2);
  EXPECT_EQ(spng_decode_image(ctx, raw.data(), raw.size(), SPNG_FMT_RAW, 0), 0);
  spng_ctx_free(ctx);
  for (std::size_t i = 0; i < values.size(); ++i)
    values[i] = static_cast<std::uint16_t>(raw[2 * i] << 8 | raw[2 * i + 1]);
  return values;
}

inline nlohmann::json readSidecar(const fs::path& file) {
  return nlohmann::json::parse(readWholeFile(file));
}

/// The default island, loaded once.
inline const strahler::construction::World& loadedWorld() {
  static const strahler::construction::World world(
      strahler::store::readWorldFile(islandWorld().string()).value());
  return world;
}

} // namespace strahler::test_support::heightmap_export
