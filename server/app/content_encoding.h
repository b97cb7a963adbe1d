#pragma once

#include <string>
#include <string_view>

namespace strahler::app {

/// True when an Accept-Encoding header value accepts the gzip content coding (RFC 9110
/// §12.5.3: "gzip" or "x-gzip" with a non-zero q, or "*" with a non-zero q and no explicit
/// gzip entry).
bool acceptsGzip(std::string_view acceptEncoding);

/// `s` without its leading and trailing spaces and tabs (HTTP's optional whitespace).
std::string_view trimmedField(std::string_view s) noexcept;

} // namespace strahler::app
