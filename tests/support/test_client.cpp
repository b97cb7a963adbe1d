#include "test_client.h"

#include <algorithm>
#include <arpa/inet.h>
#include <cerrno>
#include <cstring>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/time.h>
#include <unistd.h>

namespace strahler::http::test {
namespace {

timeval toTimeval(std::chrono::milliseconds timeout) {
  timeval tv{};
  tv.tv_sec = static_cast<time_t>(timeout.count() / 1000);
  tv.tv_usec = static_cast<suseconds_t>((timeout.count() % 1000) * 1000);
  return tv;
}

std::string lowerCase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](char c) {
    return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
  });
  return text;
}

std::string_view trimmed(std::string_view text) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t'))
    text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t'))
    text.remove_suffix(1);
  return text;
}

} // namespace

std::string RawResponse::header(std::string_view name) const {
  for (const auto& [key, value] : headers)
    if (key == name)
      return value;
  return {};
}

std::size_t RawResponse::count(std::string_view name) const {
  return static_cast<std::size_t>(std::count_if(
      headers.begin(), headers.end(), [&](const auto& field) { return field.first == name; }));
}

Connection::Connection(std::uint16_t port, std::chrono::milliseconds timeout, int receiveBuffer,
                       const std::string& sourceAddress)
    : timeout_(timeout) {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  if (fd < 0)
    return;
  if (receiveBuffer > 0)
    ::setsockopt(fd, SOL_SOCKET, SO_RCVBUF, &receiveBuffer, sizeof receiveBuffer);
  const timeval tv = toTimeval(timeout);
  ::setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof tv);
  ::setsockopt(fd, SOL_SOCKET, SO_SNDTIMEO, &tv, sizeof tv);
  if (!sourceAddress.empty()) {
    sockaddr_in source{};
    source.sin_family = AF_INET;
    if (::inet_pton(AF_INET, sourceAddress.c_str(), &source.sin_addr) != 1 ||
        ::bind(fd, reinterpret_cast<const sockaddr*>(&source), sizeof source) != 0) {
      ::close(fd);
      return;
    }
  }
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(port);
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (::connect(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address) != 0) {
    ::close(fd);
    return;
  }
  fd_ = fd;
}

Connection::~Connection() {
  close();
}

void Connection::close() noexcept {
  if (fd_ >= 0)
    ::close(fd_);
  fd_ = -1;
}

bool Connection::send(std::string_view bytes) {
  while (fd_ >= 0 && !bytes.empty()) {
    const ssize_t n = ::send(fd_, bytes.data(), bytes.size(), MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR)
      continue;
    if (n <= 0)
      return false;
    bytes.remove_prefix(static_cast<std::size_t>(n));
  }
  return fd_ >= 0;
}

bool Connection::fill() {
  if (fd_ < 0)
    return false;
  char chunk[16384];
  for (;;) {
    const ssize_t n = ::recv(fd_, chunk, sizeof chunk, 0);
    if (n < 0 && errno == EINTR)
      continue;
    if (n <= 0)
      return false;
    buffer_.append(chunk, static_cast<std::size_t>(n));
    return true;
  }
}

bool Connection::readHead(RawResponse& response) {
  std::size_t end;
  while ((end = buffer_.find("\r\n\r\n")) == std::string::npos)
    if (!fill())
      return false;
  const std::string head = buffer_.substr(0, end + 2);
  buffer_.erase(0, end + 4);
  std::size_t lineEnd = head.find("\r\n");
  const std::string statusLine = head.substr(0, lineEnd);
  const auto space = statusLine.find(' ');
  if (space == std::string::npos || statusLine.size() < space + 4)
    return false;
  response.version = statusLine.substr(0, space);
  response.status = std::atoi(statusLine.substr(space + 1, 3).c_str());
  for (std::size_t begin = lineEnd + 2; begin < head.size(); begin = lineEnd + 2) {
    lineEnd = head.find("\r\n", begin);
    const std::string_view line(head.data() + begin, lineEnd - begin);
    const auto colon = line.find(':');
    if (colon == std::string_view::npos)
      return false;
    response.headers.emplace_back(lowerCase(std::string(line.substr(0, colon))),
                                  std::string(trimmed(line.substr(colon + 1))));
  }
  return true;
}

std::optional<RawResponse> Connection::read(bool head) {
  RawResponse response;
  if (!readHead(response))
    return std::nullopt;
  if (head || response.status == 204 || response.status == 304)
    return response;
  const std::string length = response.header("content-length");
  if (length.empty())
    return std::nullopt;
  const auto size = static_cast<std::size_t>(std::stoull(length));
  while (buffer_.size() < size)
    if (!fill())
      return std::nullopt;
  response.body = buffer_.substr(0, size);
  buffer_.erase(0, size);
  return response;
}

void Connection::setReceiveTimeout(std::chrono::milliseconds timeout) {
  const timeval tv = toTimeval(timeout);
  ::setsockopt(fd_, SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof tv);
}

bool Connection::receiveUntil(std::chrono::steady_clock::time_point deadline, std::string* keep) {
  bool closed = false;
  char chunk[16384];
  while (fd_ >= 0) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0)
      break;
    setReceiveTimeout(left);
    const ssize_t n = ::recv(fd_, chunk, sizeof chunk, 0);
    if (n > 0) {
      if (keep)
        keep->append(chunk, static_cast<std::size_t>(n));
      continue;
    }
    if (n < 0 && errno == EINTR)
      continue;
    closed = n == 0 || errno == ECONNRESET;
    break;
  }
  if (fd_ >= 0)
    setReceiveTimeout(timeout_);
  return closed;
}

bool Connection::closedWithin(std::chrono::milliseconds timeout) {
  return receiveUntil(std::chrono::steady_clock::now() + timeout, nullptr);
}

std::string Connection::readUntilClose(std::chrono::milliseconds timeout) {
  std::string received = std::move(buffer_);
  buffer_.clear();
  receiveUntil(std::chrono::steady_clock::now() + timeout, &received);
  return received;
}

std::string getRequest(std::string_view target, std::string_view extraHeaders) {
  std::string request = "GET ";
  request += target;
  request += " HTTP/1.1\r\nHost: test\r\n";
  request += extraHeaders;
  request += "\r\n";
  return request;
}

std::optional<RawResponse> fetch(std::uint16_t port, std::string_view request,
                                 std::chrono::milliseconds timeout,
                                 const std::string& sourceAddress) {
  Connection connection(port, timeout, 0, sourceAddress);
  if (!connection.send(request))
    return std::nullopt;
  return connection.read(request.substr(0, 5) == "HEAD ");
}

std::string readLine(std::FILE* pipe) {
  std::string line;
  int c;
  while ((c = std::fgetc(pipe)) != EOF && c != '\n')
    line += static_cast<char>(c);
  return line;
}

} // namespace strahler::http::test
