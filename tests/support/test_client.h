#pragma once

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace strahler::http::test {

/// A response as read off the wire.
struct RawResponse {
  std::string version; ///< "HTTP/1.1".
  int status = 0;
  std::vector<std::pair<std::string, std::string>> headers; ///< Names lower-cased.
  std::string body;

  /// Value of header `name` (lower-case), or empty.
  std::string header(std::string_view name) const;
  /// Number of headers called `name` (lower-case).
  std::size_t count(std::string_view name) const;
};

/// A blocking POSIX TCP client for 127.0.0.1 that can send any bytes, malformed or not. Every
/// call is bounded by the timeout given at construction (SO_RCVTIMEO / SO_SNDTIMEO).
class Connection {
public:
  /// Connects to 127.0.0.1:`port`; `receiveBuffer` > 0 sets SO_RCVBUF before connecting.
  /// A non-empty `sourceAddress` (e.g. "127.0.0.2", which Linux routes on loopback) is bound
  /// as the client's own address, so that one test can be several clients.
  explicit Connection(std::uint16_t port,
                      std::chrono::milliseconds timeout = std::chrono::milliseconds(5000),
                      int receiveBuffer = 0, const std::string& sourceAddress = {});
  ~Connection();
  Connection(const Connection&) = delete;
  Connection& operator=(const Connection&) = delete;

  /// True when connect() succeeded.
  bool connected() const noexcept { return fd_ >= 0; }
  /// Sends all of `bytes`; false on error or timeout.
  bool send(std::string_view bytes);
  /// Reads one response (no body for `head`, 204 and 304); nullopt on EOF, timeout or garbage.
  std::optional<RawResponse> read(bool head = false);
  /// True when the server closes the connection (EOF or reset) within `timeout`; bytes that
  /// arrive meanwhile are discarded.
  bool closedWithin(std::chrono::milliseconds timeout);
  /// Everything received until the server closes or `timeout` passes.
  std::string readUntilClose(std::chrono::milliseconds timeout);
  /// Closes the socket now.
  void close() noexcept;

private:
  /// Receives more bytes into buffer_; false on EOF, error or timeout.
  bool fill();
  /// Receives until the server closes, an error or `deadline`, appending the bytes to `keep`
  /// (discarded when null); true when the server closed (EOF or reset).
  bool receiveUntil(std::chrono::steady_clock::time_point deadline, std::string* keep);
  bool readHead(RawResponse& response);
  void setReceiveTimeout(std::chrono::milliseconds timeout);

  int fd_ = -1;
  std::chrono::milliseconds timeout_;
  std::string buffer_;
};

/// "GET `target` HTTP/1.1" with a Host header and `extraHeaders` (each ending in CRLF).
std::string getRequest(std::string_view target, std::string_view extraHeaders = {});
/// Sends `request` on a fresh connection (from `sourceAddress` when not empty) and reads one
/// response, each step bounded by `timeout`.
std::optional<RawResponse>
fetch(std::uint16_t port, std::string_view request,
      std::chrono::milliseconds timeout = std::chrono::milliseconds(5000),
      const std::string& sourceAddress = {});

/// Reads one line from a pipe (a child process's output), without its newline; empty at end of
/// file.
std::string readLine(std::FILE* pipe);

} // namespace strahler::http::test
