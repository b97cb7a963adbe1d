#pragma once
// Shared by the libFuzzer harnesses: what counts as a finding besides a sanitizer report.

#include "strahler/base/result.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

namespace strahler::fuzz {

/// The input bytes as text.
inline std::string_view asText(const std::uint8_t* data, std::size_t size) noexcept {
  return {reinterpret_cast<const char*>(data), size};
}

/// Aborts (a crash for libFuzzer) when `what` holds kInternal: a reader guards itself with a
/// catch-all that turns unexpected exceptions into kInternal, and bad input must instead get
/// a precise error (README: "Bad input never crashes").
template <typename T> void requireNoInternalError(const base::Result<T>& what) {
  if (!what && what.error().code == base::ErrorCode::kInternal) {
    std::fprintf(stderr, "kInternal: %s\n", what.error().message.c_str());
    std::abort();
  }
}

/// Aborts with `message` unless `condition` holds.
inline void require(bool condition, const char* message) {
  if (!condition) {
    std::fprintf(stderr, "fuzz invariant broken: %s\n", message);
    std::abort();
  }
}

} // namespace strahler::fuzz
