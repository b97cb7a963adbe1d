#include "request_rules.h"

#include "wire_response.h"

#include <boost/beast/http/error.hpp>

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

namespace strahler::http::detail {
namespace {

/// Longest piece of client input quoted in an error message.
constexpr std::size_t kMaxQuotedBytes = 64;

Verdict reject(int status, const std::string& message, bool close) {
  return Verdict{Verdict::Kind::kReject, errorResponse(status, message), close};
}

std::string quoted(std::string_view text) {
  return "'" + std::string(text.substr(0, kMaxQuotedBytes)) + "'";
}

Verdict methodNotAllowed(std::string_view method, bool close) {
  Verdict verdict =
      reject(405, "method " + quoted(method) + " is not allowed; use GET, HEAD or OPTIONS", close);
  verdict.response.headers.emplace_back("Allow", std::string(kAllowedMethods));
  return verdict;
}

std::string_view trimmed(std::string_view text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string_view::npos)
    return {};
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

/// Beast 1.74 frames `Transfer-Encoding: gzip` requests wrongly (see PLATFORM.md), so anything
/// but a single, exact "chunked" is refused before the framing is trusted.
std::optional<Verdict> checkTransferEncoding(const bhttp::request_header<>& header) {
  const std::size_t count = header.count(bhttp::field::transfer_encoding);
  if (count == 0)
    return std::nullopt;
  if (count > 1)
    return reject(400, "repeated Transfer-Encoding header", true);
  const std::string_view value = trimmed(toStd(header[bhttp::field::transfer_encoding]));
  if (equalsIgnoreCase(value, "chunked"))
    return std::nullopt;
  return reject(400, "Transfer-Encoding " + quoted(value) + " is not supported", true);
}

std::optional<Verdict> checkHost(const bhttp::request_header<>& header) {
  const std::size_t count = header.count(bhttp::field::host);
  if (count > 1)
    return reject(400, "repeated Host header", true);
  if (count == 0 && header.version() >= 11)
    return reject(400, "HTTP/1.1 request without a Host header", true);
  return std::nullopt;
}

/// The request line (up to CR or LF) of the bytes received so far.
std::string_view requestLine(std::string_view received) {
  return received.substr(0, received.find_first_of("\r\n"));
}

/// The target of a request line, or the rest of the line when it has no second space yet.
std::string_view targetOf(std::string_view line) {
  const auto space = line.find(' ');
  if (space == std::string_view::npos)
    return {};
  const std::string_view rest = line.substr(space + 1);
  return rest.substr(0, rest.find(' '));
}

/// The space-separated parts of a request line.
std::vector<std::string_view> partsOf(std::string_view line) {
  std::vector<std::string_view> parts;
  for (std::size_t begin = 0;;) {
    const auto space = line.find(' ', begin);
    parts.push_back(line.substr(begin, space - begin));
    if (space == std::string_view::npos)
      return parts;
    begin = space + 1;
  }
}

/// "x.y" when `version` is "HTTP/x.y" with single digits, otherwise empty.
std::string versionNumber(std::string_view version) {
  const bool wellFormed = version.size() == 8 && version.substr(0, 5) == "HTTP/" &&
                          version[5] >= '0' && version[5] <= '9' && version[6] == '.' &&
                          version[7] >= '0' && version[7] <= '9';
  return wellFormed ? std::string(version.substr(5)) : std::string();
}

Verdict checkVersionError(std::string_view received) {
  const std::vector<std::string_view> parts = partsOf(requestLine(received));
  if (parts.size() != 3)
    return reject(400, "malformed request line", true);
  const std::string version = versionNumber(parts[2]);
  if (version.empty())
    return reject(400, "malformed HTTP version", true);
  if (version != "1.0" && version != "1.1")
    return reject(505, "HTTP/" + version + " is not supported; use HTTP/1.1", true);
  return reject(400, "the request line must end with CRLF", true);
}

/// Once the request line is parsed Beast drops it from the buffer, so the target comes from the
/// parser; before that, the line is still at the start of `received`.
Verdict checkHeaderLimit(const RequestParser& parser, std::string_view received,
                         const ServerOptions& options) {
  const auto& header = parser.get();
  const bool lineParsed = !header.method_string().empty();
  const std::size_t targetBytes =
      lineParsed ? header.target().size() : targetOf(requestLine(received)).size();
  if (targetBytes > options.maxTargetBytes)
    return reject(
        414, "request target exceeds " + std::to_string(options.maxTargetBytes) + " bytes", true);
  return reject(431,
                "request header block exceeds " + std::to_string(options.maxHeaderBytes) + " bytes",
                true);
}

/// The message for parse errors that need no look at the received bytes.
std::string parseErrorMessage(const ErrorCode& ec) {
  using bhttp::error;
  if (ec == error::bad_method)
    return "malformed request method";
  if (ec == error::bad_target)
    return "malformed request target";
  if (ec == error::bad_field)
    return "malformed header field name";
  if (ec == error::bad_value)
    return "malformed header field value";
  if (ec == error::bad_obs_fold)
    return "malformed folded header line";
  if (ec == error::bad_line_ending)
    return "header lines must end with CRLF";
  if (ec == error::bad_content_length)
    return "invalid Content-Length";
  if (ec == error::bad_transfer_encoding)
    return "invalid or conflicting Transfer-Encoding";
  if (ec == error::body_limit)
    return "request body not allowed";
  return "malformed request: " + ec.message();
}

} // namespace

Verdict checkRequest(const RequestParser& parser, const ServerOptions& options) {
  const auto& header = parser.get();
  const std::string_view target = toStd(header.target());
  const bool hasBody = !parser.is_done();
  if (target.size() > options.maxTargetBytes)
    return reject(414,
                  "request target is " + std::to_string(target.size()) + " bytes; the limit is " +
                      std::to_string(options.maxTargetBytes),
                  hasBody);
  if (auto verdict = checkTransferEncoding(header))
    return *verdict;
  const bhttp::verb method = header.method();
  const bool readOnly =
      method == bhttp::verb::get || method == bhttp::verb::head || method == bhttp::verb::options;
  if (hasBody && readOnly)
    return reject(400, "a " + std::string(header.method_string()) + " request must not have a body",
                  true);
  if (hasBody)
    return methodNotAllowed(toStd(header.method_string()), true);
  if (auto verdict = checkHost(header))
    return *verdict;
  if (method == bhttp::verb::options)
    return Verdict{Verdict::Kind::kPreflight, preflightResponse()};
  if (!readOnly)
    return methodNotAllowed(toStd(header.method_string()), false);
  if (target.empty() || target.front() != '/')
    return reject(400, "request target must be a path starting with '/'", true);
  return Verdict{};
}

Verdict checkParseError(const ErrorCode& ec, const RequestParser& parser, std::string_view received,
                        const ServerOptions& options) {
  if (ec == bhttp::error::header_limit)
    return checkHeaderLimit(parser, received, options);
  if (ec == bhttp::error::bad_version)
    return checkVersionError(received);
  return reject(400, parseErrorMessage(ec), true);
}

bool isParseError(const ErrorCode& ec) {
  static const auto& category = bhttp::make_error_code(bhttp::error::bad_target).category();
  return ec.category() == category && ec != bhttp::error::end_of_stream &&
         ec != bhttp::error::partial_message;
}

Request makeRequest(const bhttp::request_header<>& header, bool head,
                    const std::string& localAddress, bool fromTrustedProxy,
                    const std::shared_ptr<std::atomic<bool>>& clientGone) {
  Request request;
  request.localAddress = localAddress;
  request.fromTrustedProxy = fromTrustedProxy;
  request.clientGone = clientGone;
  request.method = "GET";
  request.head = head;
  request.target = std::string(header.target());
  for (const auto& field : header) {
    std::string name(field.name_string());
    std::transform(name.begin(), name.end(), name.begin(), [](char c) {
      return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
    });
    request.headers.emplace_back(std::move(name), std::string(field.value()));
  }
  return request;
}

} // namespace strahler::http::detail
