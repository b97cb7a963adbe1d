#pragma once

#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/beast/core/error.hpp>
#include <boost/beast/core/string.hpp>
#include <boost/beast/http/empty_body.hpp>
#include <boost/beast/http/message.hpp>
#include <boost/beast/http/parser.hpp>
#include <boost/optional.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

namespace strahler::http::detail {

namespace net = boost::asio;
namespace beast = boost::beast;
namespace bhttp = boost::beast::http;
using tcp = net::ip::tcp;
using ErrorCode = beast::error_code;

/// The parser of one request header; requests never have a body here.
using RequestParser = bhttp::request_parser<bhttp::empty_body>;
/// A Beast body that sends a shared, immutable string without copying it: cached tiles go
/// out straight from the cache. Write-only (responses).
struct SharedStringBody {
  using value_type = std::shared_ptr<const std::string>;

  /// Body size for Content-Length.
  static std::uint64_t size(const value_type& body) noexcept { return body ? body->size() : 0; }

  /// Serialises the body as one buffer.
  class writer {
  public:
    using const_buffers_type = net::const_buffer;

    template <bool isRequest, class Fields>
    writer(const bhttp::header<isRequest, Fields>&, const value_type& body) : body_(body) {}
    void init(ErrorCode& ec) { ec = {}; }
    boost::optional<std::pair<const_buffers_type, bool>> get(ErrorCode& ec) {
      ec = {};
      if (!body_ || body_->empty())
        return boost::none;
      return std::make_pair(const_buffers_type(body_->data(), body_->size()), false);
    }

  private:
    const value_type& body_;
  };
};

/// Size of a wire response's body (0 when there is none).
template <class Message> std::size_t bodySize(const Message& m) noexcept {
  return m.body() ? m.body()->size() : 0;
}

/// A response as written to the socket.
using WireResponse = bhttp::response<SharedStringBody>;

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
