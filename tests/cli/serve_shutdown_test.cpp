// The real `strahler serve` under a load of expensive distinct tiles exits on SIGTERM within its
// drain window, with status 0: queued tiles are dropped (503), only running ones finish
// (issue 17, item 3).
#include "serve_process.h"
#include "test_client.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;
using namespace std::chrono_literals;

/// serve's drain window (kDrainWindow in server/app/serve_command.cpp).
constexpr auto kDrainWindow = 4000ms;
/// Allowed beyond it: the tiles still being computed at the deadline (one 1024² EXR tile
/// takes a few hundred ms here) and tearing the process down.
constexpr auto kExitMargin = 1500ms;
constexpr int kClients = 200;

TEST(ServeCommand, SigtermUnderLoadExitsWithinTheDrainWindow) {
  const std::string scratch = std::string(STRAHLER_BINARY_DIR) + "/cli_test_scratch/shutdown";
  strahler::test_support::ServeProcess serve(
      {STRAHLER_EXECUTABLE, "serve", "--quiet", "--port", "0", "--threads", "2", "--workers", "2"},
      "STRAHLER_CACHE_DIR=" + scratch);
  ASSERT_GT(serve.pid(), 0) << "cannot start " << STRAHLER_EXECUTABLE;
  std::string banner;
  const std::uint16_t port = serve.readPort(&banner);
  ASSERT_NE(port, 0) << "no banner, got '" << banner << "'";

  // One EXR tile first: the OpenImageIO module, loaded on first use (~0.5 s), is there before
  // the load and the clock start.
  const auto first = strahler::http::test::fetch(
      port, strahler::http::test::getRequest("/worlds/default/tiles/15/13856/11935.exr?size=16"),
      30s);
  ASSERT_TRUE(first && first->status == 200);

  // Distinct 1024² EXR tiles over the island at zoom 15 (the cache cannot help): two workers
  // need tens of seconds for all of them.
  std::mutex mutex;
  std::map<int, int> statuses; // 0: no response
  std::atomic<int> sent{0};
  std::vector<std::thread> clients;
  for (int i = 0; i < kClients; ++i)
    clients.emplace_back([&, i] {
      strahler::http::test::Connection connection(port, 20s);
      const std::string target = "/worlds/default/tiles/15/" + std::to_string(13856 + i % 32) +
                                 "/" + std::to_string(11936 + i / 32) + ".exr?size=1024";
      int status = 0;
      if (connection.send(strahler::http::test::getRequest(target))) {
        ++sent;
        if (const auto response = connection.read())
          status = response->status;
      }
      std::lock_guard lock(mutex);
      ++statuses[status];
    });
  const auto loaded = Clock::now() + 5s;
  while (sent.load() < kClients && Clock::now() < loaded)
    std::this_thread::sleep_for(10ms);
  std::this_thread::sleep_for(1s); // the workers are busy, the queue is full
  const auto start = Clock::now();
  ASSERT_EQ(::kill(serve.pid(), SIGTERM), 0);
  const auto status = serve.waitUntil(start + kDrainWindow + kExitMargin);
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  for (std::thread& client : clients)
    client.join(); // the server has closed every connection (or is killed by ~ServeProcess)
  ASSERT_TRUE(status) << "still running " << seconds << " s after SIGTERM";
  EXPECT_TRUE(WIFEXITED(*status) && WEXITSTATUS(*status) == 0) << "wait status " << *status;
  EXPECT_EQ(sent.load(), kClients);
  std::string tally;
  for (const auto& [code, count] : statuses)
    tally += " " + std::to_string(code) + ":" + std::to_string(count);
  std::printf("exit %.2f s after SIGTERM; statuses (0 = none):%s\n", seconds, tally.c_str());
  for (const auto& [code, count] : statuses)
    EXPECT_TRUE(code == 200 || code == 503) << count << " requests got " << code << tally;
}

} // namespace
