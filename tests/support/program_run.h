#pragma once

#include <filesystem>
#include <string>

namespace strahler::test_support {

/// What one run of a program printed, and how it ended (-1: it did not exit normally).
struct ProcessRun {
  int exitCode = -1;
  std::string out;
  std::string err;
};

/// A folder of this process's own (created if needed): `root`/`name`-<pid>, so that tests
/// CTest runs in parallel processes never share one.
std::filesystem::path processScratchDir(const std::filesystem::path& root, const std::string& name);

/// The whole contents of a file ("" if it cannot be read).
std::string readWholeFile(const std::filesystem::path& path);

/// Runs `executable args` (a shell command line) to its end with STRAHLER_CACHE_DIR set to
/// `scratch`/cache, never the user's cache; standard error passes through `scratch`/stderr.txt.
ProcessRun runProgram(const std::string& executable, const std::string& args,
                      const std::filesystem::path& scratch);

} // namespace strahler::test_support
