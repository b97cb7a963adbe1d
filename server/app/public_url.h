#pragma once

#include "strahler/base/result.h"
#include "strahler/http/http_types.h"

#include <string>

namespace strahler::app {

/// Validates the --public-url of `strahler serve`: "http://" or "https://", a host (DNS name,
/// IPv4 address or [IPv6 address]), an optional :port (1..65535) and an optional path prefix;
/// no user info, query or fragment. Returns it with the scheme and host lower-cased and without
/// a trailing '/', ready to have "/worlds/..." appended; kInvalidInput saying what is wrong
/// otherwise.
base::Result<std::string> parsePublicUrl(const std::string& url);

/// The origin of absolute URLs in the answer to `request`: `publicUrl` (from parsePublicUrl)
/// when set; else, from a trusted proxy, X-Forwarded-Proto (http or https) and
/// X-Forwarded-Host (host[:port]; the first value of each) in place of "http" and the address
/// the client connected to; else "http://" + that address. Never the Host header.
/// kInvalidInput naming the header when a trusted proxy sends a malformed one.
base::Result<std::string> requestOrigin(const std::string& publicUrl, const http::Request& request);

} // namespace strahler::app
