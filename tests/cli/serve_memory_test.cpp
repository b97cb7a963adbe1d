// The real `strahler serve` filled with many distinct tiles over HTTP: its resident memory
// stays within --cache-mb plus a documented constant (issue 17, item 1).
#include "test_client.h"

#include <gtest/gtest.h>

#include <atomic>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

namespace {

using strahler::http::test::readLine;

/// Resident memory allowed above the bound: what tile computations leave in the allocator's
/// arenas (fragmented by the cached tiles between them) and the I/O buffers. Measured growth
/// with 2 workers (docs/performance.md): 4,000 small tiles +2..3 MB (before the cache charged
/// capacity: +100 MB); then 24 tiles of 1024² +1 MB with the trimmer and its fixed mmap
/// threshold, +7..55 MB with the trimmer alone, +53 MB with neither.
constexpr long kRssSlackMb = 16;
constexpr long kCacheMb = 4;

/// VmRSS of process `pid` in MB, or -1.
long residentMb(pid_t pid) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmRSS:", 0) == 0)
      return std::stol(line.substr(6)) / 1024;
  return -1;
}

/// Requests `targets` on `connections` keep-alive connections (connection c takes targets c,
/// c + connections, ...); returns how many connections met a status other than 200.
int requestAll(std::uint16_t port, const std::vector<std::string>& targets, int connections,
               std::chrono::seconds timeout) {
  std::atomic<int> failed{0};
  std::vector<std::thread> clients;
  for (int c = 0; c < connections; ++c)
    clients.emplace_back([&, c] {
      strahler::http::test::Connection connection(port, timeout);
      for (std::size_t i = static_cast<std::size_t>(c); i < targets.size();
           i += static_cast<std::size_t>(connections)) {
        const auto r = connection.send(strahler::http::test::getRequest(targets[i]))
                           ? connection.read()
                           : std::nullopt;
        if (!r || r->status != 200) {
          ++failed;
          return;
        }
      }
    });
  for (std::thread& t : clients)
    t.join();
  return failed.load();
}

/// Requests the 1024² EXR tiles of the island at zoom 13 (x 3464.., y 2984..), `count` of them,
/// on two keep-alive connections; returns how many connections met a status other than 200.
int requestLargeLandTiles(std::uint16_t port, int count) {
  std::vector<std::string> targets;
  for (int i = 0; i < count; ++i)
    targets.push_back("/worlds/default/tiles/13/" + std::to_string(3464 + i % 8) + "/" +
                      std::to_string(2984 + i / 8) + ".exr?size=1024");
  return requestAll(port, targets, 2, std::chrono::seconds(60));
}

/// Requests the far-sea PNG tiles 18/x/5000 for x in [first, first + count) on four keep-alive
/// connections; returns how many connections met a status other than 200.
int requestTiles(std::uint16_t port, int first, int count) {
  std::vector<std::string> targets;
  for (int x = first; x < first + count; ++x)
    targets.push_back("/worlds/default/tiles/18/" + std::to_string(1000 + x) + "/5000.png");
  return requestAll(port, targets, 4, std::chrono::seconds(30));
}

TEST(ServeCommand, ResidentMemoryStaysWithinTheCacheBound) {
  const std::string scratch = std::string(STRAHLER_BINARY_DIR) + "/cli_test_scratch/memory";
  const std::string command = "echo $$; STRAHLER_CACHE_DIR=" + scratch + " exec " +
                              std::string(STRAHLER_EXECUTABLE) +
                              " serve --quiet --port 0 --threads 2 --workers 2 --cache-mb " +
                              std::to_string(kCacheMb) + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  const pid_t pid = static_cast<pid_t>(std::stol(readLine(pipe)));
  const std::string banner = readLine(pipe);
  const std::size_t colon = banner.rfind(':');
  if (colon == std::string::npos) {
    ::kill(pid, SIGKILL);
    pclose(pipe);
    FAIL() << banner;
  }
  const auto port = static_cast<std::uint16_t>(std::stoi(banner.substr(colon + 1)));
  // Warm up: threads, arenas and buffers exist, 400 tiles are cached, and the OpenImageIO
  // module that EXR tiles load on first use is there (~120 MB of RSS once, docs/performance.md).
  EXPECT_EQ(requestTiles(port, 0, 400), 0);
  EXPECT_EQ(requestAll(port, {"/worlds/default/tiles/18/1000/5000.exr?size=16"}, 1,
                       std::chrono::seconds(30)),
            0);
  const long warm = residentMb(pid);
  // ~4,000 distinct tiles: about twice what 4 MB holds, so the cache fills and evicts.
  EXPECT_EQ(requestTiles(port, 400, 4000), 0);
  const long filled = residentMb(pid);
  // A burst of large tiles (~20 MB of temporaries each) that the cache cannot keep many of:
  // what the allocator keeps afterwards is given back within a second (MemoryTrimmer).
  EXPECT_EQ(requestLargeLandTiles(port, 24), 0);
  // The trimmer gives freed heap back at most once a second after tiles were computed; on a
  // loaded machine (the suite runs two tests at once) its pass can come late, so wait for it
  // up to 6 s rather than a fixed 1.5 s. Memory the server keeps is not given back at all, so
  // it still fails the bound.
  long afterBurst = 0;
  for (int wait = 0; wait < 24; ++wait) {
    std::this_thread::sleep_for(std::chrono::milliseconds(250));
    afterBurst = residentMb(pid);
    if (wait >= 5 && afterBurst - warm <= kCacheMb + kRssSlackMb)
      break;
  }
  const auto metrics = strahler::http::test::fetch(
      port, strahler::http::test::getRequest("/metrics"), std::chrono::seconds(10));
  ::kill(pid, SIGTERM);
  for (std::string line; !(line = readLine(pipe)).empty() || !std::feof(pipe);) {
  }
  pclose(pipe);
  ASSERT_GT(warm, 0);
  EXPECT_LE(filled - warm, kCacheMb + kRssSlackMb)
      << "RSS " << warm << " MB after warming up, " << filled << " MB after 4,000 tiles";
  EXPECT_LE(afterBurst - warm, kCacheMb + kRssSlackMb)
      << "RSS " << warm << " MB after warming up, " << afterBurst
      << " MB up to 6 s after 24 tiles of 1024²";
  ASSERT_TRUE(metrics);
  EXPECT_NE(metrics->body.find("strahler_tile_cache_evictions_total"), std::string::npos);
  EXPECT_EQ(metrics->body.find("strahler_tile_cache_evictions_total 0."), std::string::npos)
      << "the cache never filled";
}

} // namespace
