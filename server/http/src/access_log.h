#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace strahler::http::detail {

/// Longest request target written to the access log, in bytes (longer ones end in "...").
inline constexpr std::size_t kMaxLoggedTargetBytes = 200;

/// One access-log line without the newline: `METHOD target status bytes ms`. The target is cut
/// to kMaxLoggedTargetBytes; control, space, backslash and non-ASCII bytes in method and target
/// are written as \xHH so that one request is always exactly one line; `ms` has one decimal.
std::string formatAccessLine(std::string_view method, std::string_view target, int status,
                             std::size_t bytes, double ms);

/// Writes `line` plus a newline to stdout in one call, so concurrent lines never interleave.
void writeAccessLine(const std::string& line) noexcept;

} // namespace strahler::http::detail
