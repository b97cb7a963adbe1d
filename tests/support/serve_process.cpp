#include "serve_process.h"

#include <csignal>
#include <fstream>
#include <spawn.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

extern char** environ;

namespace strahler::test_support {

ServeProcess::ServeProcess(const std::vector<std::string>& args,
                           const std::string& extraEnvironment) {
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
  if (posix_spawn(&pid_, argv[0], &actions, nullptr, argv.data(), env.data()) != 0)
    pid_ = -1;
  posix_spawn_file_actions_destroy(&actions);
  ::close(fds[1]);
  out_ = ::fdopen(fds[0], "r");
}

ServeProcess::~ServeProcess() {
  if (pid_ > 0) {
    ::kill(pid_, SIGKILL);
    ::waitpid(pid_, nullptr, 0);
  }
  if (out_)
    std::fclose(out_);
}

std::string ServeProcess::readLine() const {
  std::string line;
  if (!out_)
    return line;
  for (int c; (c = std::fgetc(out_)) != EOF && c != '\n';)
    line += static_cast<char>(c);
  return line;
}

std::uint16_t ServeProcess::readPort(std::string* banner) const {
  const std::string line = readLine();
  if (banner)
    *banner = line;
  const std::size_t colon = line.rfind(':');
  if (colon == std::string::npos || colon + 1 == line.size())
    return 0;
  try {
    const int port = std::stoi(line.substr(colon + 1));
    return port > 0 && port < 65536 ? static_cast<std::uint16_t>(port) : 0;
  } catch (const std::exception&) {
    return 0;
  }
}

std::optional<int> ServeProcess::waitUntil(Clock::time_point deadline) {
  for (;;) {
    int status = 0;
    if (pid_ > 0 && ::waitpid(pid_, &status, WNOHANG) == pid_) {
      pid_ = -1;
      return status;
    }
    if (pid_ <= 0 || Clock::now() > deadline)
      return std::nullopt;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
}

long ServeProcess::residentMb() const {
  std::ifstream status("/proc/" + std::to_string(pid_) + "/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmRSS:", 0) == 0)
      return std::stol(line.substr(6)) / 1024;
  return -1;
}

} // namespace strahler::test_support
