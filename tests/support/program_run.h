#pragma once

#include <filesystem>
#include <string>

namespace strahler::testing {

/// What one run of a program printed, and how it ended (-1: it did not exit normally).
struct ProcessRun {
  int exitCode = -1;
  std::string out;
  std::string err;
};

/// Runs `executable args` (a shell command line) to its end with STRAHLER_CACHE_DIR set to
/// `scratch`/cache, never the user's cache; standard error passes through `scratch`/stderr.txt.
ProcessRun runProgram(const std::string& executable, const std::string& args,
                      const std::filesystem::path& scratch);

} // namespace strahler::testing
