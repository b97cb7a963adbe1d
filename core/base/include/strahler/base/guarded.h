#pragma once

#include "strahler/base/result.h"

#include <exception>
#include <new>
#include <string>
#include <string_view>

namespace strahler::base {

/// How guarded() words what a call threw, each message starting "<label>: ".
struct GuardWords {
  std::string_view label;                         ///< What failed: "params", "png encoder".
  std::string_view outOfMemory = "out of memory"; ///< Said of std::bad_alloc (kLimitExceeded).
  ErrorCode failure = ErrorCode::kInternal;       ///< The code of any other std::exception.
  std::string_view failurePrefix = "unexpected failure: "; ///< Said before its what().
};

/// fn()'s result (a Result or a Status), or an Error when fn throws: kLimitExceeded
/// "<label>: <outOfMemory>" for std::bad_alloc, `failure` "<label>: <failurePrefix><what()>"
/// for another std::exception, kInternal "<label>: unknown failure" for anything else. The
/// one guard at the edge of a stage or a third-party library, so that one bad input or one
/// failed allocation fails its call and not the process.
template <class Fn> auto guarded(const GuardWords& words, Fn&& fn) -> decltype(fn()) {
  const auto said = [&](std::string_view what) {
    std::string message(words.label);
    message += ": ";
    message += what;
    return message;
  };
  try {
    return fn();
  } catch (const std::bad_alloc&) {
    return makeError(ErrorCode::kLimitExceeded, said(words.outOfMemory));
  } catch (const std::exception& e) {
    return makeError(words.failure, said(std::string(words.failurePrefix) + e.what()));
  } catch (...) {
    return makeError(ErrorCode::kInternal, said("unknown failure"));
  }
}

/// guarded() with the usual words: "<label>: out of memory", kInternal "<label>: unexpected
/// failure: <what()>".
template <class Fn> auto guarded(std::string_view label, Fn&& fn) -> decltype(fn()) {
  return guarded(GuardWords{label}, static_cast<Fn&&>(fn));
}

} // namespace strahler::base
