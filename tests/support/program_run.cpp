#include "program_run.h"

#include <array>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

namespace strahler::test_support {

std::filesystem::path processScratchDir(const std::filesystem::path& root,
                                        const std::string& name) {
  const std::filesystem::path dir = root / (name + "-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return dir;
}

std::string readWholeFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

ProcessRun runProgram(const std::string& executable, const std::string& args,
                      const std::filesystem::path& scratch) {
  const std::filesystem::path errPath = scratch / "stderr.txt";
  const std::string command = "STRAHLER_CACHE_DIR=" + (scratch / "cache").string() + " " +
                              executable + " " + args + " 2>" + errPath.string();
  ProcessRun run;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe)
    return run;
  std::array<char, 4096> buffer{};
  std::size_t n;
  while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0)
    run.out.append(buffer.data(), n);
  const int status = pclose(pipe);
  run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream in(errPath, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  run.err = text.str();
  return run;
}

} // namespace strahler::test_support
