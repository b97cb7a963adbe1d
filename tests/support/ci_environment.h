#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <string_view>

namespace strahler::test_support {

/// True when the environment says CI=true (CI sets it): data that CI provides must be there.
inline bool runningInCi() {
  const char* ci = std::getenv("CI");
  return ci != nullptr && std::string_view(ci) == "true";
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
