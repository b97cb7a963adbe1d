#include "strahler/base/assert.h"
#include "strahler/base/result.h"

#include <cstdio>
#include <cstdlib>

namespace strahler::base {

const char* errorCodeName(ErrorCode code) noexcept {
  switch (code) {
  case ErrorCode::kInvalidInput:
    return "invalid_input";
  case ErrorCode::kOutOfRange:
    return "out_of_range";
  case ErrorCode::kLimitExceeded:
    return "limit_exceeded";
  case ErrorCode::kNotFound:
    return "not_found";
  case ErrorCode::kIoError:
    return "io_error";
  case ErrorCode::kCorrupt:
    return "corrupt";
  case ErrorCode::kUnsupported:
    return "unsupported";
  case ErrorCode::kInternal:
    return "internal";
  }
  return "unknown";
}

void assertionFailed(const char* condition, const char* message, const char* file,
                     int line) noexcept {
  std::fprintf(stderr, "strahler: assertion failed: %s (%s) at %s:%d\n", condition, message, file,
               line);
  std::abort();
}

} // namespace strahler::base
