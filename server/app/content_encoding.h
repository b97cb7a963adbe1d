#pragma once

#include <string>
#include <string_view>

namespace strahler::app {

/// True when an Accept-Encoding header value accepts the gzip content coding (RFC 9110
/// §12.5.3: "gzip" or "x-gzip" with a non-zero q, or "*" with a non-zero q and no explicit
/// gzip entry).
bool acceptsGzip(std::string_view acceptEncoding);

} // namespace strahler::app
