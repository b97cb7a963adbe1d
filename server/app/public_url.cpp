#include "public_url.h"

#include <algorithm>
#include <cctype>

namespace strahler::app {
namespace {

base::Error badUrl(const std::string& url, const std::string& why) {
  return base::makeError(base::ErrorCode::kInvalidInput,
                         "--public-url '" + url.substr(0, 200) + "': " + why);
}

bool isDnsChar(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '.';
}

/// Characters of a path prefix: RFC 3986 pchar and '/', percent escapes included.
bool isPathChar(char c) {
  static const std::string kAllowed = "-._~!$&'()*+,;=:@/%";
  return std::isalnum(static_cast<unsigned char>(c)) || kAllowed.find(c) != std::string::npos;
}

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

/// `authority` ("host[:port]") with the host lower-cased, or why it is not one.
base::Result<std::string> normaliseAuthority(const std::string& authority) {
  const auto bad = [](const std::string& why) {
    return base::makeError(base::ErrorCode::kInvalidInput, why);
  };
  if (authority.find('@') != std::string::npos)
    return bad("user info is not allowed");
  std::string host = authority, port;
  bool portGiven = false;
  if (!authority.empty() && authority[0] == '[') {
    const std::size_t close = authority.find(']');
    if (close == std::string::npos)
      return bad("unclosed '[' in the host");
    host = authority.substr(0, close + 1);
    const std::string inner = authority.substr(1, close - 1);
    if (inner.empty() || inner.find_first_not_of("0123456789abcdefABCDEF:.") != std::string::npos)
      return bad("'" + host.substr(0, 100) + "' is not an IPv6 address");
    if (close + 1 < authority.size()) {
      if (authority[close + 1] != ':')
        return bad("expected ':' and a port after the IPv6 address");
      port = authority.substr(close + 2);
      portGiven = true;
    }
  } else if (const std::size_t c = authority.find(':'); c != std::string::npos) {
    host = authority.substr(0, c);
    port = authority.substr(c + 1);
    portGiven = true;
  }
  if (host.empty())
    return bad("has no host");
  if (host[0] != '[' && (!std::all_of(host.begin(), host.end(), isDnsChar) || host[0] == '.' ||
                         host[0] == '-' || host.find("..") != std::string::npos))
    return bad("'" + host.substr(0, 100) + "' is not a host name or address");
  if (portGiven) {
    const bool digits = !port.empty() && port.size() <= 5 &&
                        port.find_first_not_of("0123456789") == std::string::npos;
    if (!digits || std::stoi(port) < 1 || std::stoi(port) > 65535)
      return bad("port must be a number in 1..65535");
  }
  return portGiven ? lower(host) + ":" + port : lower(host);
}

/// The first value of a comma-separated header (a proxy chain appends), trimmed.
std::string firstValue(const std::string& header) {
  const std::string first = header.substr(0, header.find(','));
  const std::size_t begin = first.find_first_not_of(" \t");
  if (begin == std::string::npos)
    return "";
  return first.substr(begin, first.find_last_not_of(" \t") - begin + 1);
}

} // namespace

base::Result<std::string> parsePublicUrl(const std::string& url) {
  const std::size_t colon = url.find("://");
  if (colon == std::string::npos)
    return badUrl(url, "must start with http:// or https://");
  const std::string scheme = lower(url.substr(0, colon));
  if (scheme != "http" && scheme != "https")
    return badUrl(url, "scheme must be http or https, not '" + scheme.substr(0, 20) + "'");
  const std::size_t hostStart = colon + 3;
  const std::size_t pathStart = std::min(url.find('/', hostStart), url.size());
  const std::string authority = url.substr(hostStart, pathStart - hostStart);
  std::string path = url.substr(pathStart);
  if (url.find_first_of("?#") != std::string::npos)
    return badUrl(url, "a query or fragment is not allowed");
  auto host = normaliseAuthority(authority);
  if (!host)
    return badUrl(url, host.error().message);
  if (!std::all_of(path.begin(), path.end(), isPathChar))
    return badUrl(url, "the path may hold only URL path characters");
  while (!path.empty() && path.back() == '/')
    path.pop_back();
  return scheme + "://" + host.value() + path;
}

base::Result<std::string> requestOrigin(const std::string& publicUrl,
                                        const http::Request& request) {
  if (!publicUrl.empty())
    return publicUrl;
  std::string scheme = "http", authority = request.localAddress;
  if (request.fromTrustedProxy) {
    if (const std::string proto = firstValue(request.header("x-forwarded-proto")); !proto.empty()) {
      scheme = lower(proto);
      if (scheme != "http" && scheme != "https")
        return base::makeError(base::ErrorCode::kInvalidInput, "X-Forwarded-Proto '" +
                                                                   proto.substr(0, 100) +
                                                                   "': must be http or https");
    }
    if (const std::string host = firstValue(request.header("x-forwarded-host")); !host.empty()) {
      auto checked = normaliseAuthority(host);
      if (!checked)
        return base::makeError(base::ErrorCode::kInvalidInput, "X-Forwarded-Host '" +
                                                                   host.substr(0, 100) +
                                                                   "': " + checked.error().message);
      authority = checked.value();
    }
  }
  return scheme + "://" + authority;
}

} // namespace strahler::app
