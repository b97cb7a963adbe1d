#include "command_support.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace strahler::app {

int fail(const base::Error& error) {
  std::fprintf(stderr, "strahler: error: %s\n", error.message.c_str());
  return 1;
}

int usageError(const base::Error& error, const char* usage) {
  std::fprintf(stderr, "strahler: %s\n%s", error.message.c_str(), usage);
  return 2;
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
