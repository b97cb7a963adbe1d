#include "result_matchers.h"

#include "strahler/base/result.h"

#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace strahler::base {
namespace {

Result<int> half(int x) {
  if (x % 2 != 0)
    return makeError(ErrorCode::kInvalidInput, "odd");
  return x / 2;
}

Result<int> quarter(int x) {
  STRAHLER_ASSIGN_OR_RETURN(int h, half(x));
  return half(h);
}

TEST(Result, CarriesValueOrError) {
  EXPECT_EQ(test_support::valueOf(half(4)), 2);
  EXPECT_FALSE(half(3).ok());
  EXPECT_EQ(half(3).error().message, "odd");
  EXPECT_EQ(half(3).error().code, ErrorCode::kInvalidInput);
}

TEST(Result, AssignOrReturnPropagatesTheFirstError) {
  EXPECT_EQ(test_support::valueOf(quarter(8)), 2);
  EXPECT_EQ(quarter(6).error().message, "odd");
  EXPECT_EQ(quarter(5).error().message, "odd");
}

/// quarter() that says which step failed; `contexts` counts the contexts built.
Result<int> quarterSaying(int x, int& contexts) {
  const auto context = [&contexts](std::string what) {
    ++contexts;
    return what;
  };
  STRAHLER_ASSIGN_OR_RETURN(int h, half(x), context("halving " + std::to_string(x)));
  STRAHLER_RETURN_IF_ERROR(half(h), context("halving again"));
  return h / 2;
}

TEST(Result, AnOptionalContextGoesBeforeTheMessageOfAPassedOnError) {
  int contexts = 0;
  EXPECT_EQ(quarterSaying(5, contexts).error().message, "halving 5: odd");
  EXPECT_EQ(quarterSaying(5, contexts).error().code, ErrorCode::kInvalidInput);
  EXPECT_EQ(quarterSaying(6, contexts).error().message, "halving again: odd");
  EXPECT_EQ(contexts, 3);
  EXPECT_EQ(test_support::valueOf(quarterSaying(8, contexts)), 2);
  EXPECT_EQ(contexts, 3) << "a context is built only for an error";
}

TEST(Result, WithContextKeepsTheCodeAndPrefixesTheMessage) {
  const Error e = withContext(makeError(ErrorCode::kCorrupt, "bad CRC"), "world.bin");
  EXPECT_EQ(e.code, ErrorCode::kCorrupt);
  EXPECT_EQ(e.message, "world.bin: bad CRC");
  EXPECT_EQ(withContext(makeError(ErrorCode::kCorrupt, "bad CRC")).message, "bad CRC");
}

void assertOkOnAnError() {
  STRAHLER_ASSERT_OK(half(3));
}

void assignOrAssertOnAnError() {
  STRAHLER_ASSIGN_OR_ASSERT([[maybe_unused]] const int h, half(3));
}

TEST(TestSupport, ResultAssertionsFailOneTestWithTheExpressionCodeAndMessage) {
  EXPECT_FATAL_FAILURE(assertOkOnAnError(), "half(3): invalid_input: odd");
  EXPECT_FATAL_FAILURE(assignOrAssertOnAnError(), "half(3): invalid_input: odd");
  EXPECT_THROW(test_support::valueOf(half(3)), std::runtime_error);
}

TEST(ErrorCode, HasStableNames) {
  EXPECT_STREQ(errorCodeName(ErrorCode::kLimitExceeded), "limit_exceeded");
  EXPECT_STREQ(errorCodeName(ErrorCode::kCorrupt), "corrupt");
}

} // namespace
} // namespace strahler::base
