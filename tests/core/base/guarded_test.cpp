// base::guarded: a call's result passes through; what it throws becomes an Error in the
// guard's words (out of memory, another exception, anything else).
#include "strahler/base/guarded.h"

#include <gtest/gtest.h>

#include <new>
#include <stdexcept>

namespace strahler::base {
namespace {

TEST(Guarded, PassesTheResultThrough) {
  const Result<int> value = guarded("params", [] { return Result<int>(7); });
  ASSERT_TRUE(value.ok());
  EXPECT_EQ(value.value(), 7);
  const Result<int> error = guarded(
      "params", []() -> Result<int> { return makeError(ErrorCode::kOutOfRange, "too big"); });
  ASSERT_FALSE(error.ok());
  EXPECT_EQ(error.error().code, ErrorCode::kOutOfRange);
  EXPECT_EQ(error.error().message, "too big");
}

TEST(Guarded, TurnsWhatIsThrownIntoErrorsInItsWords) {
  const auto thrown = [](auto&& words, auto exception) {
    return guarded(words, [&]() -> Status { throw exception; });
  };
  const Status memory = thrown("params", std::bad_alloc());
  EXPECT_EQ(memory.error().code, ErrorCode::kLimitExceeded);
  EXPECT_EQ(memory.error().message, "params: out of memory");
  const Status failure = thrown("params", std::runtime_error("boom"));
  EXPECT_EQ(failure.error().code, ErrorCode::kInternal);
  EXPECT_EQ(failure.error().message, "params: unexpected failure: boom");
  const Status other = thrown("params", 42);
  EXPECT_EQ(other.error().code, ErrorCode::kInternal);
  EXPECT_EQ(other.error().message, "params: unknown failure");

  const GuardWords words{.label = "coastline",
                         .outOfMemory = "out of memory while repairing",
                         .failure = ErrorCode::kInvalidInput,
                         .failurePrefix = "could not mend: "};
  EXPECT_EQ(thrown(words, std::bad_alloc()).error().message,
            "coastline: out of memory while repairing");
  const Status mended = thrown(words, std::runtime_error("a pinch"));
  EXPECT_EQ(mended.error().code, ErrorCode::kInvalidInput);
  EXPECT_EQ(mended.error().message, "coastline: could not mend: a pinch");
}

} // namespace
} // namespace strahler::base
