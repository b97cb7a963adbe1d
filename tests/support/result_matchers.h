#pragma once
// Results in tests: matchers and assertions that fail one test with the error's message
// (where Result::value() on an error would abort the whole test binary).

#include "strahler/base/result.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

namespace strahler::test_support {

/// "code: message" of an error, for failure messages.
inline std::string describe(const base::Error& error) {
  return std::string(base::errorCodeName(error.code)) + ": " + error.message;
}

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

/// The value of `result`; on an error, throws std::runtime_error with its code and message,
/// which GoogleTest reports as a failure of the running test alone. For places where
/// STRAHLER_ASSIGN_OR_ASSERT cannot return (helpers that return a value, expressions).
template <class T> T valueOf(base::Result<T>&& result) {
  if (!result.ok())
    throw std::runtime_error(describe(result.error()));
  return std::move(result).value();
}

/// The value of `result` (a copy), or the same throw as above.
template <class T> T valueOf(const base::Result<T>& result) {
  if (!result.ok())
    throw std::runtime_error(describe(result.error()));
  return result.value();
}

} // namespace strahler::test_support

/// Fails the running test (fatally: returns from the enclosing void function) with the
/// expression, the error code and message when the Result or Status holds an error.
#define STRAHLER_ASSERT_OK(...)                                                                    \
  do {                                                                                             \
    const auto& strahler_checked_ = (__VA_ARGS__);                                                 \
    ASSERT_TRUE(strahler_checked_.ok())                                                            \
        << #__VA_ARGS__ << ": " << ::strahler::test_support::describe(strahler_checked_.error());  \
  } while (false)

/// Declares or assigns `lhs` from the value of the Result, or fails the running test as
/// STRAHLER_ASSERT_OK does. In a void function only (a test body, a void helper).
#define STRAHLER_ASSIGN_OR_ASSERT(lhs, ...)                                                        \
  STRAHLER_ASSIGN_OR_ASSERT_IMPL(STRAHLER_CONCAT(strahler_test_result_, __LINE__), lhs, __VA_ARGS__)
#define STRAHLER_ASSIGN_OR_ASSERT_IMPL(tmp, lhs, ...)                                              \
  auto tmp = (__VA_ARGS__);                                                                        \
  ASSERT_TRUE(tmp.ok()) << #__VA_ARGS__ << ": "                                                    \
                        << ::strahler::test_support::describe(tmp.error());                        \
  lhs = std::move(tmp).value()
