#pragma once

namespace strahler::base {

/// Reports a failed programmer assertion and aborts; never returns.
[[noreturn]] void assertionFailed(const char* condition, const char* message, const char* file,
                                  int line) noexcept;

} // namespace strahler::base

/// Checks an invariant that only a bug can break (never user input); active in every build.
#define STRAHLER_ASSERT(condition, message)                                                        \
  do {                                                                                             \
    if (!(condition))                                                                              \
      ::strahler::base::assertionFailed(#condition, message, __FILE__, __LINE__);                  \
  } while (false)
