// The real `strahler serve` under a load of expensive distinct tiles exits on SIGTERM within its
// drain window, with status 0: queued tiles are dropped (503), only running ones finish
// (issue 17, item 3).
#include "test_client.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <map>
#include <mutex>
#include <optional>
#include <spawn.h>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

extern char** environ;

namespace {

using Clock = std::chrono::steady_clock;
using namespace std::chrono_literals;

/// serve's drain window (kDrainWindow in server/app/serve_command.cpp).
constexpr auto kDrainWindow = 4000ms;
/// Allowed beyond it: the tiles still being computed at the deadline (one 1024² EXR tile
/// takes a few hundred ms here) and tearing the process down.
constexpr auto kExitMargin = 1500ms;
constexpr int kClients = 200;

/// `strahler serve` as a child of this process (so its exit status can be read), stdout piped.
struct ServeProcess {
  pid_t pid = -1;
  FILE* out = nullptr;

  /// Starts `args` with `extraEnvironment` ("NAME=value") added to this process's.
  ServeProcess(const std::vector<std::string>& args, const std::string& extraEnvironment) {
    int fds[2];
    if (::pipe(fds) != 0)
      return;
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[1], STDOUT_FILENO);
    posix_spawn_file_actions_addclose(&actions, fds[0]);
    std::vector<char*> argv;
    for (const std::string& arg : args)
      argv.push_back(const_cast<char*>(arg.c_str()));
    argv.push_back(nullptr);
    std::vector<char*> env;
    for (char** e = environ; *e; ++e)
      env.push_back(*e);
    env.push_back(const_cast<char*>(extraEnvironment.c_str()));
    env.push_back(nullptr);
    if (posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), env.data()) != 0)
      pid = -1;
    posix_spawn_file_actions_destroy(&actions);
    ::close(fds[1]);
    out = ::fdopen(fds[0], "r");
  }
  ~ServeProcess() {
    if (pid > 0) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, nullptr, 0);
    }
    if (out)
      std::fclose(out);
  }

  /// The next line of stdout (without the newline); empty at EOF.
  std::string readLine() const {
    std::string line;
    for (int c; (c = std::fgetc(out)) != EOF && c != '\n';)
      line += static_cast<char>(c);
    return line;
  }

  /// Waits until the process exits or `deadline` passes; its wait status, or nothing.
  std::optional<int> waitUntil(Clock::time_point deadline) {
    for (;;) {
      int status = 0;
      if (::waitpid(pid, &status, WNOHANG) == pid) {
        pid = -1;
        return status;
      }
      if (Clock::now() > deadline)
        return std::nullopt;
      std::this_thread::sleep_for(10ms);
    }
  }
};

TEST(ServeCommand, SigtermUnderLoadExitsWithinTheDrainWindow) {
  const std::string scratch = std::string(STRAHLER_BINARY_DIR) + "/cli_test_scratch/shutdown";
  ServeProcess serve(
      {STRAHLER_EXECUTABLE, "serve", "--quiet", "--port", "0", "--threads", "2", "--workers", "2"},
      "STRAHLER_CACHE_DIR=" + scratch);
  ASSERT_GT(serve.pid, 0) << "cannot start " << STRAHLER_EXECUTABLE;
  const std::string banner = serve.readLine();
  const std::size_t colon = banner.rfind(':');
  ASSERT_NE(colon, std::string::npos) << "no banner, got '" << banner << "'";
  const auto port = static_cast<std::uint16_t>(std::stoi(banner.substr(colon + 1)));

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
  ASSERT_EQ(::kill(serve.pid, SIGTERM), 0);
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
