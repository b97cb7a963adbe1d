#include "result_matchers.h"

#include "strahler/base/result.h"

#include <gtest/gtest.h>

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

TEST(ErrorCode, HasStableNames) {
  EXPECT_STREQ(errorCodeName(ErrorCode::kLimitExceeded), "limit_exceeded");
  EXPECT_STREQ(errorCodeName(ErrorCode::kCorrupt), "corrupt");
}

} // namespace
} // namespace strahler::base
