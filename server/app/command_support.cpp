#include "command_support.h"

#include "strahler/store/world_file.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace strahler::app {

int fail(const base::Error& error) {
  std::fprintf(stderr, "strahler: error: %s\n", error.message.c_str());
  return 1;
}

int usageError(const base::Error& error, const std::string& command) {
  std::fprintf(stderr, "strahler: error: %s\nsee 'strahler %s--help'\n", error.message.c_str(),
               command.empty() ? "" : (command + " ").c_str());
  return 2;
}

namespace {

/// True when the file's first byte that is not white space opens a JSON object.
bool looksLikeJson(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char c = 0;
  while (in.get(c))
    if (c != ' ' && c != '\t' && c != '\r' && c != '\n')
      return c == '{';
  return false;
}

} // namespace

base::Result<construction::WorldData> readWorldArgument(const std::string& path,
                                                        const std::string& hint) {
  auto world = store::readWorldFile(path);
  if (world.ok() || !looksLikeJson(path))
    return world;
  return base::makeError(base::ErrorCode::kInvalidInput,
                         "'" + path + "' is GeoJSON, not a world file: " + hint);
}

std::string generateFirstHint(const std::string& path) {
  const std::string stem = std::filesystem::path(path).stem().string();
  return "make its world first with 'strahler generate --coast " + path + " -o " +
         (stem.empty() ? "world" : stem) + ".world'";
}

int printUsage(const char* usage) {
  std::fputs(usage, stdout);
  return 0;
}

void printRepairsAndWarnings(const input::WorldSpec& spec) {
  for (const repair::Change& change : spec.repairs)
    std::fprintf(stderr, "strahler: repaired: %s\n", repair::describe(change).c_str());
  for (const std::string& warning : spec.warnings)
    std::fprintf(stderr, "strahler: warning: %s\n", warning.c_str());
}

bool endsWith(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

base::Status writeTextFile(const std::string& path, const std::string& text) {
  const std::string temporary = path + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out << text;
    if (!out.flush()) {
      std::error_code ignored;
      std::filesystem::remove(temporary, ignored);
      return base::makeError(base::ErrorCode::kIoError, "cannot write '" + path + "'");
    }
  }
  std::error_code ec;
  std::filesystem::rename(temporary, path, ec);
  if (ec)
    return base::makeError(base::ErrorCode::kIoError,
                           "cannot write '" + path + "': " + ec.message());
  return base::Ok{};
}

} // namespace strahler::app
