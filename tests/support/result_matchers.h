#pragma once

#include "strahler/base/result.h"

#include <gtest/gtest.h>

#include <string>
#include <string_view>

namespace strahler::testing {

/// Passes when `result` is an error with `code` whose message contains `part`.
template <class T>
::testing::AssertionResult failsWith(const base::Result<T>& result, base::ErrorCode code,
                                     std::string_view part) {
  if (result.ok())
    return ::testing::AssertionFailure() << "expected an error, got a value";
  const base::Error& e = result.error();
  if (e.code != code)
    return ::testing::AssertionFailure() << "code " << base::errorCodeName(e.code) << ", expected "
                                         << base::errorCodeName(code) << ": " << e.message;
  if (e.message.find(part) == std::string::npos)
    return ::testing::AssertionFailure()
           << "message \"" << e.message << "\" lacks \"" << part << "\"";
  return ::testing::AssertionSuccess() << e.message;
}

} // namespace strahler::testing
