#include "access_log.h"

#include <cstdio>
#include <stdio.h> // flockfile, funlockfile (POSIX)

namespace strahler::http::detail {
namespace {

/// Appends `text` with every byte outside printable ASCII (and space, backslash) as \xHH.
void appendEscaped(std::string& out, std::string_view text) {
  static constexpr char kHex[] = "0123456789abcdef";
  for (char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte > 0x20 && byte < 0x7F && c != '\\') {
      out += c;
    } else {
      out += "\\x";
      out += kHex[byte >> 4];
      out += kHex[byte & 0xF];
    }
  }
}

} // namespace

std::string formatAccessLine(std::string_view method, std::string_view target, int status,
                             std::size_t bytes, double ms) {
  std::string line;
  line.reserve(64 + target.size());
  appendEscaped(line, method.empty() ? std::string_view("-") : method);
  line += ' ';
  appendEscaped(line,
                target.empty() ? std::string_view("-") : target.substr(0, kMaxLoggedTargetBytes));
  if (target.size() > kMaxLoggedTargetBytes)
    line += "...";
  char numbers[64];
  std::snprintf(numbers, sizeof numbers, " %d %zu %.1f", status, bytes, ms < 0.0 ? 0.0 : ms);
  line += numbers;
  return line;
}

void writeAccessLine(const std::string& line) noexcept {
  flockfile(stdout);
  std::fwrite(line.data(), 1, line.size(), stdout);
  std::fputc('\n', stdout);
  std::fflush(stdout);
  funlockfile(stdout);
}

} // namespace strahler::http::detail
