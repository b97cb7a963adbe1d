// The real `strahler serve` under two faults of hostile or unlucky clients (issue 17, standing
// fault tests): slow readers of large tiles, and more unique tiles than the workers and their
// queue can take. Real HTTP over sockets on 127.0.0.1; clients bind 127.0.0.x source addresses
// (Linux routes all of 127/8 on loopback) to stay under the per-client connection limit. Each
// test prints its figures (docs/performance.md, "HTTP server: slow readers and overload").
#include "serve_process.h"
#include "test_client.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace {

using strahler::http::test::Connection;
using strahler::http::test::fetch;
using strahler::http::test::getRequest;
using strahler::test_support::ServeProcess;
using Clock = std::chrono::steady_clock;
using namespace std::chrono_literals;

/// `strahler serve` on an ephemeral port with 2 I/O threads and 2 workers, the default island
/// generated into (or loaded from) a scratch cache directory.
ServeProcess startServe(const std::string& scratchName, const std::vector<std::string>& extra) {
  std::vector<std::string> args = {STRAHLER_EXECUTABLE, "serve", "--quiet",   "--port", "0",
                                   "--threads",         "2",     "--workers", "2"};
  args.insert(args.end(), extra.begin(), extra.end());
  return ServeProcess(args, "STRAHLER_CACHE_DIR=" + std::string(STRAHLER_BINARY_DIR) +
                                "/cli_test_scratch/" + scratchName);
}

/// Client address `i` of a test: 127.0.0.(10 + i).
std::string clientAddress(int i) {
  return "127.0.0." + std::to_string(10 + i);
}

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

std::string tally(const std::map<int, int>& statuses) {
  std::string out;
  for (const auto& [code, count] : statuses)
    out += " " + std::to_string(code) + ":" + std::to_string(count);
  return out;
}

/// Sockets open in process `pid` (its listener and connections).
int openSockets(pid_t pid) {
  int n = 0;
  for (const auto& entry :
       std::filesystem::directory_iterator("/proc/" + std::to_string(pid) + "/fd")) {
    std::error_code ec;
    if (std::filesystem::read_symlink(entry.path(), ec).string().rfind("socket:", 0) == 0)
      ++n;
  }
  return n;
}

/// A 1024² EXR tile of the default island at zoom 13 (x 3464..3471, y 2984..): a few MB.
std::string largeTile(int i) {
  return "/worlds/default/tiles/13/" + std::to_string(3464 + i % 8) + "/" +
         std::to_string(2984 + i / 8) + ".exr?size=1024";
}

/// Slow readers: clients that ask for large tiles and then read nothing (a receive window of a
/// few KB that never drains) hold their connections and the server's writes. The server keeps
/// answering everyone else at once, and the bodies it holds for them are the cached tiles'
/// bytes, shared, not copies: memory stays within the cache bound plus the usual slack.
TEST(ServeCommand, SlowReadersOfLargeTilesDoNotStopOthersAndMemoryStaysBounded) {
  constexpr int kSlowReaders = 200; // 4 addresses × 50 (< 64 per address)
  constexpr int kLargeTiles = 8;
  constexpr long kCacheMb = 64;
  constexpr long kRssSlackMb = 32; // as serve_memory_test.cpp: allocator and I/O buffers
  ServeProcess serve = startServe("slow_readers", {"--cache-mb", std::to_string(kCacheMb)});
  ASSERT_GT(serve.pid(), 0) << "cannot start " << STRAHLER_EXECUTABLE;
  std::string banner;
  const std::uint16_t port = serve.readPort(&banner);
  ASSERT_NE(port, 0) << "no banner, got '" << banner << "'";

  // The large tiles once, read normally: they are cached, and their size is known.
  std::size_t tileBytes = 0;
  for (int t = 0; t < kLargeTiles; ++t) {
    const auto r = fetch(port, getRequest(largeTile(t)), 60s, clientAddress(0));
    ASSERT_TRUE(r && r->status == 200) << largeTile(t);
    tileBytes = std::max(tileBytes, r->body.size());
  }
  const long warm = serve.residentMb();

  std::vector<std::unique_ptr<Connection>> slow;
  for (int i = 0; i < kSlowReaders; ++i) {
    auto c =
        std::make_unique<Connection>(port, 5000ms, 4096, "127.0.0." + std::to_string(2 + i / 50));
    ASSERT_TRUE(c->connected()) << "slow reader " << i;
    // Four pipelined requests each, so that every reader has several MB owed to it.
    std::string requests;
    for (int k = 0; k < 4; ++k)
      requests += getRequest(largeTile((i + k) % kLargeTiles));
    ASSERT_TRUE(c->send(requests)) << "slow reader " << i;
    slow.push_back(std::move(c));
  }
  std::this_thread::sleep_for(2s); // the server has written what the windows take, and waits

  // Others: eight clients, 25 requests each (health and small tiles, some computed), each on a
  // fresh connection.
  std::mutex mutex;
  std::map<int, int> statuses;
  double slowest = 0.0;
  std::vector<std::thread> others;
  const auto othersStart = Clock::now();
  for (int c = 0; c < 8; ++c)
    others.emplace_back([&, c] {
      for (int k = 0; k < 25; ++k) {
        const std::string target =
            k % 2 ? "/health"
                  : "/worlds/default/tiles/18/" + std::to_string(2000 + 25 * c + k) + "/5000.png";
        const auto start = Clock::now();
        const auto r = fetch(port, getRequest(target), 10s, clientAddress(1 + c));
        const double seconds = secondsSince(start);
        std::lock_guard lock(mutex);
        ++statuses[r ? r->status : 0];
        slowest = std::max(slowest, seconds);
      }
    });
  for (std::thread& t : others)
    t.join();
  const double othersSeconds = secondsSince(othersStart);
  const long held = serve.residentMb();
  const int sockets = openSockets(serve.pid());
  slow.clear(); // the readers go away
  const auto after = fetch(port, getRequest("/health"), 10s, clientAddress(0));

  std::printf("slow readers: %d connections owed %d x %zu-byte tiles each (%.0f MB owed); "
              "server sockets %d; RSS %ld MB warm, %ld MB with the readers; others:%s, "
              "200 requests in %.2f s, slowest %.3f s\n",
              kSlowReaders, 4, tileBytes, kSlowReaders * 4.0 * double(tileBytes) / 1e6, sockets,
              warm, held, tally(statuses).c_str(), othersSeconds, slowest);
  EXPECT_EQ(statuses[200], 200) << tally(statuses);
  EXPECT_GE(sockets, kSlowReaders) << "the slow readers were dropped, not held";
  // 0.02-0.06 s on a quiet machine; the bound leaves room for a machine busy with other work.
  EXPECT_LT(slowest, 5.0) << "a normal request waited behind the slow readers";
  EXPECT_LE(held - warm, kCacheMb + kRssSlackMb)
      << "RSS " << warm << " MB before the slow readers, " << held << " MB with them";
  ASSERT_TRUE(after);
  EXPECT_EQ(after->status, 200);
}

/// A unique 1024² EXR tile of the island at zoom 15 (~0.1-0.3 s of a worker each).
std::string uniqueTile(int i) {
  return "/worlds/default/tiles/15/" + std::to_string(13840 + i % 48) + "/" +
         std::to_string(11920 + i / 48) + ".exr?size=1024";
}

/// Overload: far more unique (uncacheable) tiles than two workers and the 256-tile queue can
/// take. Every answer is 200 or 503 with Retry-After, health stays immediate, and once the
/// clients have given up the server serves a fresh tile within 5 s (the work of clients that
/// are gone is dropped, not computed).
TEST(ServeCommand, OverloadWithUniqueTilesAnswers200Or503AndRecoversWithinFiveSeconds) {
  constexpr int kClients = 480;  // 8 addresses × 60 (< 64 per address)
  constexpr auto kPatience = 3s; // then a client gives up and closes, as a browser does
  constexpr double kRecoverySeconds = 5.0;
  ServeProcess serve = startServe("overload", {});
  ASSERT_GT(serve.pid(), 0) << "cannot start " << STRAHLER_EXECUTABLE;
  std::string banner;
  const std::uint16_t port = serve.readPort(&banner);
  ASSERT_NE(port, 0) << "no banner, got '" << banner << "'";

  std::mutex mutex;
  std::map<int, int> statuses; // 0: gave up before an answer
  int without503RetryAfter = 0;
  std::atomic<int> sent{0};
  std::vector<std::thread> clients;
  const auto start = Clock::now();
  for (int i = 0; i < kClients; ++i)
    clients.emplace_back([&, i] {
      Connection c(port, kPatience, 0, clientAddress(i / 60));
      int status = -1; // -1: could not send
      bool retryAfter = true;
      if (c.connected() && c.send(getRequest(uniqueTile(i)))) {
        ++sent;
        const auto r = c.read();
        status = r ? r->status : 0;
        if (r && r->status == 503)
          retryAfter = !r->header("retry-after").empty();
      }
      std::lock_guard lock(mutex);
      ++statuses[status];
      without503RetryAfter += retryAfter ? 0 : 1;
    });
  // Health during the overload: answered on the I/O threads, not queued behind the tiles.
  std::this_thread::sleep_for(500ms);
  const auto healthStart = Clock::now();
  const auto health = fetch(port, getRequest("/health"), 5s, "127.0.0.3");
  const double healthSeconds = secondsSince(healthStart);
  for (std::thread& t : clients)
    t.join();
  const double loadSeconds = secondsSince(start);

  // Recovery: a fresh tile (never asked for) is served 200 within 5 s of the clients leaving.
  const auto leftAt = Clock::now();
  int attempts = 0;
  int recoveredStatus = 0;
  while (secondsSince(leftAt) < 2 * kRecoverySeconds) {
    const auto r = fetch(port, getRequest(uniqueTile(kClients + attempts)), 10s, "127.0.0.4");
    ++attempts;
    recoveredStatus = r ? r->status : 0;
    if (recoveredStatus == 200)
      break;
    std::this_thread::sleep_for(100ms);
  }
  const double recovery = secondsSince(leftAt);
  const auto metrics = fetch(port, getRequest("/metrics"), 10s, "127.0.0.4");
  std::string cancelled = "?";
  if (metrics) {
    const std::size_t at = metrics->body.find("\nstrahler_tile_computations_cancelled_total ");
    if (at != std::string::npos)
      cancelled = metrics->body.substr(at + 44, metrics->body.find('\n', at + 1) - at - 44);
  }

  std::printf("overload: %d clients of unique 1024^2 EXR tiles, patience 3 s: statuses "
              "(0 = gave up)%s in %.2f s; 503 without Retry-After: %d; health during it %.3f s; "
              "fresh tile 200 %.2f s after the clients left (%d attempts); queued tiles "
              "dropped: %s\n",
              kClients, tally(statuses).c_str(), loadSeconds, without503RetryAfter, healthSeconds,
              recovery, attempts, cancelled.c_str());
  EXPECT_EQ(sent.load(), kClients);
  for (const auto& [code, count] : statuses)
    EXPECT_TRUE(code == 0 || code == 200 || code == 503) << count << " got " << code;
  EXPECT_GT(statuses[503], 0) << "no overload: the queue never filled" << tally(statuses);
  EXPECT_GT(statuses[200], 0) << tally(statuses);
  EXPECT_EQ(without503RetryAfter, 0);
  ASSERT_TRUE(health);
  EXPECT_EQ(health->status, 200);
  EXPECT_LT(healthSeconds, 1.0);
  EXPECT_EQ(recoveredStatus, 200);
  EXPECT_LE(recovery, kRecoverySeconds);
}

} // namespace
