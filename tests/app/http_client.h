#pragma once

// A minimal blocking HTTP/1.1 client over POSIX sockets, for tests against 127.0.0.1.
#include <arpa/inet.h>
#include <cstdint>
#include <map>
#include <netinet/in.h>
#include <string>
#include <sys/socket.h>
#include <sys/time.h>
#include <unistd.h>

namespace strahler::testing {

struct HttpResponse {
  int status = 0; ///< 0 when the connection failed or closed before a status line.
  std::map<std::string, std::string> headers; ///< Lower-cased names.
  std::string body;
};

/// Sends raw bytes on a new connection and reads one response (bounded by a 20 s timeout).
inline HttpResponse sendRaw(std::uint16_t port, const std::string& bytes, bool expectBody = true) {
  HttpResponse out;
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  if (fd < 0)
    return out;
  timeval timeout{20, 0};
  ::setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &timeout, sizeof timeout);
  ::setsockopt(fd, SOL_SOCKET, SO_SNDTIMEO, &timeout, sizeof timeout);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_port = htons(port);
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (::connect(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0) {
    ::close(fd);
    return out;
  }
  for (std::size_t sent = 0; sent < bytes.size();) {
    const ssize_t n = ::send(fd, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL);
    if (n <= 0)
      break;
    sent += static_cast<std::size_t>(n);
  }
  std::string data;
  char buffer[65536];
  std::size_t headerEnd = std::string::npos, needed = std::string::npos;
  for (;;) {
    const ssize_t n = ::recv(fd, buffer, sizeof buffer, 0);
    if (n <= 0)
      break;
    data.append(buffer, static_cast<std::size_t>(n));
    if (headerEnd == std::string::npos &&
        (headerEnd = data.find("\r\n\r\n")) != std::string::npos) {
      const std::string head = data.substr(0, headerEnd);
      std::size_t lineEnd = head.find("\r\n");
      out.status = std::atoi(head.substr(9, 3).c_str());
      while (lineEnd != std::string::npos && lineEnd < head.size()) {
        const std::size_t next = head.find("\r\n", lineEnd + 2);
        const std::string line = head.substr(
            lineEnd + 2, (next == std::string::npos ? head.size() : next) - lineEnd - 2);
        const std::size_t colon = line.find(':');
        if (colon != std::string::npos) {
          std::string name = line.substr(0, colon);
          for (char& c : name)
            c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
          out.headers[name] = line.substr(line.find_first_not_of(' ', colon + 1));
        }
        lineEnd = next;
      }
      const auto length = out.headers.find("content-length");
      needed = headerEnd + 4 +
               (expectBody && length != out.headers.end() ? std::stoul(length->second) : 0);
    }
    if (needed != std::string::npos && data.size() >= needed)
      break;
  }
  ::close(fd);
  if (headerEnd != std::string::npos)
    out.body = data.substr(headerEnd + 4);
  return out;
}

/// GET (or another method) of `target` with Connection: close.
inline HttpResponse request(std::uint16_t port, const std::string& target,
                            const std::string& method = "GET",
                            const std::string& extraHeaders = "") {
  return sendRaw(port,
                 method + " " + target + " HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port) +
                     "\r\nConnection: close\r\n" + extraHeaders + "\r\n",
                 method != "HEAD");
}

} // namespace strahler::testing
