#pragma once

#include "strahler/base/result.h"

#include <string>

namespace strahler::app {

/// Validates the --public-url of `strahler serve`: "http://" or "https://", a host (DNS name,
/// IPv4 address or [IPv6 address]), an optional :port (1..65535) and an optional path prefix;
/// no user info, query or fragment. Returns it with the scheme and host lower-cased and without
/// a trailing '/', ready to have "/worlds/..." appended; kInvalidInput saying what is wrong
/// otherwise.
base::Result<std::string> parsePublicUrl(const std::string& url);

} // namespace strahler::app
