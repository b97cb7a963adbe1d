#pragma once

#include <boost/asio/basic_waitable_timer.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core/error.hpp>
#include <boost/beast/core/string.hpp>
#include <boost/beast/http/empty_body.hpp>
#include <boost/beast/http/message.hpp>
#include <boost/beast/http/parser.hpp>

#include <chrono>
#include <string_view>

namespace strahler::http::detail {

namespace net = boost::asio;
namespace beast = boost::beast;
namespace bhttp = boost::beast::http;
using tcp = net::ip::tcp;
using ErrorCode = beast::error_code;

/// The parser of one request header; requests never have a body here.
using RequestParser = bhttp::request_parser<bhttp::empty_body>;
/// The executor of one I/O thread's event loop. Sockets and timers use it directly (no strand,
/// no type-erased executor): each event loop is run by exactly one thread.
using Executor = net::io_context::executor_type;
/// A connection's socket, bound to its I/O thread.
using Socket = tcp::socket::rebind_executor<Executor>::other;
/// A timer bound to an I/O thread.
using Timer = net::basic_waitable_timer<std::chrono::steady_clock,
                                        net::wait_traits<std::chrono::steady_clock>, Executor>;

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
