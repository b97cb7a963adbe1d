#pragma once

#include "net.h"

#include "strahler/http/http_server.h"
#include "strahler/http/http_types.h"

#include <atomic>
#include <memory>
#include <string>
#include <string_view>

namespace strahler::http::detail {

/// What the server does with a request before, or instead of, calling the handler.
struct Verdict {
  enum class Kind {
    kForward,   ///< A valid GET or HEAD: the handler answers.
    kPreflight, ///< OPTIONS: `response` is the 204 preflight answer.
    kReject,    ///< `response` is the JSON error answer.
  };
  Kind kind = Kind::kForward;
  Response response;  ///< For kPreflight and kReject.
  bool close = false; ///< Close the connection after answering: the framing cannot be trusted.
};

/// Applies the protocol rules to a completely parsed request header, in this order: target
/// longer than maxTargetBytes → 414; Transfer-Encoding other than one "chunked" → 400; any body
/// (Content-Length > 0 or chunked) → 400 on GET/HEAD/OPTIONS, 405 otherwise, both closing;
/// HTTP/1.1 without exactly one Host → 400; OPTIONS → preflight; GET/HEAD with a target that is
/// not origin-form ("/...") → 400, closing like every 400; any other method (case-sensitive)
/// → 405 with Allow.
Verdict checkRequest(const RequestParser& parser, const ServerOptions& options);

/// The answer to a header that `parser` rejected with `ec`, always closing. `received` holds the
/// unconsumed bytes read so far; with the parser they tell a too-long target (414) from a
/// too-large header block (431), and an unsupported "HTTP/x.y" (505) from a malformed request
/// line (400).
Verdict checkParseError(const ErrorCode& ec, const RequestParser& parser, std::string_view received,
                        const ServerOptions& options);

/// True for a parser error that deserves an answer (checkParseError); end of stream, a truncated
/// message (the peer closed) and socket errors do not.
bool isParseError(const ErrorCode& ec);

/// The handler's view of a parsed request header: target as sent, header names lower-cased,
/// method "GET" (`head` tells HEAD apart). Only for requests checkRequest() forwards.
Request makeRequest(const bhttp::request_header<>& header, bool head,
                    const std::string& localAddress, bool fromTrustedProxy,
                    const std::shared_ptr<std::atomic<bool>>& clientGone);

} // namespace strahler::http::detail
