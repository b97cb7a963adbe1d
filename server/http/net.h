#pragma once

#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/beast/core/error.hpp>
#include <boost/beast/core/string.hpp>
#include <boost/beast/http/empty_body.hpp>
#include <boost/beast/http/message.hpp>
#include <boost/beast/http/parser.hpp>
#include <boost/beast/http/string_body.hpp>

#include <string_view>

namespace strahler::http::detail {

namespace net = boost::asio;
namespace beast = boost::beast;
namespace bhttp = boost::beast::http;
using tcp = net::ip::tcp;
using ErrorCode = beast::error_code;

/// The parser of one request header; requests never have a body here.
using RequestParser = bhttp::request_parser<bhttp::empty_body>;
/// A response as written to the socket.
using WireResponse = bhttp::response<bhttp::string_body>;

/// A Beast (boost::) string_view as a std::string_view.
inline std::string_view toStd(beast::string_view text) noexcept {
  return {text.data(), text.size()};
}

/// A std::string_view as a Beast (boost::) string_view.
inline beast::string_view toBeast(std::string_view text) noexcept {
  return {text.data(), text.size()};
}

/// ASCII case-insensitive equality (header names, tokens).
inline bool equalsIgnoreCase(std::string_view a, std::string_view b) noexcept {
  return beast::iequals(toBeast(a), toBeast(b));
}

} // namespace strahler::http::detail
