#pragma once

#include "strahler/base/assert.h"

#include <string>
#include <string_view>
#include <utility>
#include <variant>

namespace strahler::base {

/// What kind of thing went wrong; the server maps these to HTTP statuses in one place.
enum class ErrorCode {
  kInvalidInput,  ///< Malformed or inconsistent user input (GeoJSON, params, images).
  kOutOfRange,    ///< A well-formed value outside its documented range.
  kLimitExceeded, ///< Input larger than a documented cap (vertices, area, nesting, bytes).
  kNotFound,      ///< A file or named thing that does not exist.
  kIoError,       ///< The operating system refused a read or write.
  kCorrupt,       ///< Stored data failed a checksum, version or bounds check.
  kUnsupported,   ///< A request for a feature or format strahler does not have.
  kInternal,      ///< A bug or an impossible state reached through valid input.
};

/// Stable lower-case name of an error code, e.g. "invalid_input".
const char* errorCodeName(ErrorCode code) noexcept;

/// An error a user can act on: a code and a message naming what and where.
struct Error {
  ErrorCode code = ErrorCode::kInternal;
  std::string message;
};

/// Either a value or an Error, never both (draco's StatusOr, without exceptions).
template <class T> class [[nodiscard]] Result {
public:
  Result(T value) : state_(std::move(value)) {}
  Result(Error error) : state_(std::move(error)) {}

  /// True when a value is present.
  bool ok() const noexcept { return state_.index() == 0; }
  explicit operator bool() const noexcept { return ok(); }

  /// The value; asserts ok().
  T& value() & {
    STRAHLER_ASSERT(ok(), "Result::value() on an error");
    return std::get<0>(state_);
  }
  const T& value() const& {
    STRAHLER_ASSERT(ok(), "Result::value() on an error");
    return std::get<0>(state_);
  }
  T&& value() && {
    STRAHLER_ASSERT(ok(), "Result::value() on an error");
    return std::get<0>(std::move(state_));
  }

  /// The error; asserts !ok().
  const Error& error() const& {
    STRAHLER_ASSERT(!ok(), "Result::error() on a value");
    return std::get<1>(state_);
  }
  Error&& error() && {
    STRAHLER_ASSERT(!ok(), "Result::error() on a value");
    return std::get<1>(std::move(state_));
  }

private:
  std::variant<T, Error> state_;
};

/// Success without a value.
struct Ok {};
using Status = Result<Ok>;

/// Builds an Error with the given code and message.
inline Error makeError(ErrorCode code, std::string message) {
  return Error{code, std::move(message)};
}

/// `error` with `context` and ": " before its message (the code is kept), so an error passed
/// up through a caller also says what the caller was doing; unchanged without a context.
inline Error withContext(Error error) {
  return error;
}
inline Error withContext(Error error, std::string_view context) {
  error.message.insert(0, std::string(context) + ": ");
  return error;
}

} // namespace strahler::base

#define STRAHLER_CONCAT_INNER(a, b) a##b
#define STRAHLER_CONCAT(a, b) STRAHLER_CONCAT_INNER(a, b)

/// Returns the error of `expr` (a Result) from the enclosing function, if any. An optional
/// third argument, a string evaluated only on an error, is put before its message
/// (base::withContext): STRAHLER_RETURN_IF_ERROR(write(path), "saving " + path).
#define STRAHLER_RETURN_IF_ERROR(expr, ...)                                                        \
  do {                                                                                             \
    auto&& strahler_status_ = (expr);                                                              \
    if (!strahler_status_.ok())                                                                    \
      return ::strahler::base::withContext(                                                        \
          std::move(strahler_status_).error() __VA_OPT__(, ) __VA_ARGS__);                         \
  } while (false)

/// Declares `lhs` from the value of `expr` (a Result), or returns its error, with an optional
/// context before its message as above: STRAHLER_ASSIGN_OR_RETURN(auto w, read(p), "world " + p).
#define STRAHLER_ASSIGN_OR_RETURN(lhs, expr, ...)                                                  \
  STRAHLER_ASSIGN_OR_RETURN_IMPL(STRAHLER_CONCAT(strahler_result_, __LINE__), lhs,                 \
                                 expr __VA_OPT__(, ) __VA_ARGS__)
#define STRAHLER_ASSIGN_OR_RETURN_IMPL(tmp, lhs, expr, ...)                                        \
  auto tmp = (expr);                                                                               \
  if (!tmp.ok())                                                                                   \
    return ::strahler::base::withContext(std::move(tmp).error() __VA_OPT__(, ) __VA_ARGS__);       \
  lhs = std::move(tmp).value()
