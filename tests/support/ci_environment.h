#pragma once

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string_view>

namespace strahler::test_support {

/// True when the environment says CI=true (CI sets it): data that CI provides must be there.
inline bool runningInCi() {
  const char* ci = std::getenv("CI");
  return ci != nullptr && std::string_view(ci) == "true";
}

/// Says that this machine lacks `what` (an instruction set, e.g. "AVX-512"), so `test` leaves
/// that path unchecked here: never a silent skip. Under CI=true the line also goes to stderr,
/// which CI's log keeps; the portable build (scripts/test-portable.sh) checks the portable path.
inline void noteMissingHardware(std::string_view test, std::string_view what) {
  std::printf("[ MISSING  ] %.*s: this machine lacks %.*s; that path is not checked here\n",
              static_cast<int>(test.size()), test.data(), static_cast<int>(what.size()),
              what.data());
  if (runningInCi())
    std::fprintf(stderr, "CI: %.*s: this machine lacks %.*s; that path is not checked here\n",
                 static_cast<int>(test.size()), test.data(), static_cast<int>(what.size()),
                 what.data());
}

} // namespace strahler::test_support

/// Ends the test for want of data outside the project (`message` names it): a skip on a
/// developer's machine, a failure under CI=true, where a skip would hide the test.
#define STRAHLER_SKIP_UNLESS_CI(message)                                                           \
  do {                                                                                             \
    if (::strahler::test_support::runningInCi())                                                   \
      GTEST_FAIL() << message << " (CI=true, and CI provides it)";                                 \
    else                                                                                           \
      GTEST_SKIP() << message;                                                                     \
  } while (false)
