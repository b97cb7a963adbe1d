#pragma once
// A tile server over the default island on real sockets (127.0.0.1, an ephemeral port), and a
// one-request client: what the server's endpoint tests share.
#include "test_client.h"
#include "test_worlds.h"
#include "tile_server.h"

#include "strahler/construction/world_builder.h"
#include "strahler/http/http_server.h"

#include <gtest/gtest.h>

#include <chrono>
#include <map>
#include <string>

namespace strahler::app::test_support {

/// A response with its headers by lower-case name, as these tests read them.
struct HttpResponse {
  int status = 0; ///< 0 when no response came.
  std::map<std::string, std::string> headers;
  std::string body;
};

/// `method` of `target` with Connection: close on a fresh connection (each step bounded by
/// 20 s).
inline HttpResponse request(std::uint16_t port, const std::string& target,
                            const std::string& method = "GET",
                            const std::string& extraHeaders = "") {
  const std::string bytes = method + " " + target +
                            " HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port) +
                            "\r\nConnection: close\r\n" + extraHeaders + "\r\n";
  HttpResponse out;
  if (const auto r = http::test::fetch(port, bytes, std::chrono::seconds(20))) {
    out.status = r->status;
    for (const auto& [name, value] : r->headers)
      out.headers[name] = value;
    out.body = r->body;
  }
  return out;
}

/// A running server over the default island (or `world`, also served as "island").
struct Running {
  TileServer tiles;
  http::Server server;
  explicit Running(std::size_t cacheBytes = 64u << 20, std::string publicUrl = "",
                   http::TrustedProxies trusted = {})
      : Running(construction::generateWorldData(strahler::test_support::defaultIslandSpec(), "k")
                    .value(),
                cacheBytes, std::move(publicUrl), std::move(trusted)) {}
  explicit Running(construction::WorldData world, std::size_t cacheBytes = 64u << 20,
                   std::string publicUrl = "", http::TrustedProxies trusted = {})
      : tiles({{"island", std::move(world)}}, serverOptions(cacheBytes, std::move(publicUrl))),
        server(
            options(std::move(trusted)),
            [this](const http::Request& r, std::function<void(http::Response)> done) {
              tiles.handle(r, std::move(done));
            },
            [this](const std::string& route, int status, std::size_t bytes, double ms) {
              tiles.observe(route, status, bytes, ms);
            }) {
    EXPECT_TRUE(server.start().ok());
  }
  static TileServerOptions serverOptions(std::size_t cacheBytes, std::string publicUrl) {
    TileServerOptions o;
    o.workers = 2;
    o.cacheBytes = cacheBytes;
    o.publicUrl = std::move(publicUrl);
    return o;
  }
  static http::ServerOptions options(http::TrustedProxies trusted) {
    http::ServerOptions o;
    o.port = 0;
    o.accessLog = false;
    o.trustedProxies = std::move(trusted);
    return o;
  }
  std::uint16_t port() const { return server.port(); }
};

/// Expects `target` to be refused with `status` and a JSON error whose message holds `message`
/// (the client learns what was wrong, not only that something was).
inline void expectRefused(std::uint16_t port, const std::string& target, int status,
                          const std::string& message, const std::string& extraHeaders = "") {
  const HttpResponse r = request(port, target, "GET", extraHeaders);
  EXPECT_EQ(r.status, status) << target << " " << r.body;
  EXPECT_EQ(r.headers.count("content-type") ? r.headers.at("content-type") : "", "application/json")
      << target;
  EXPECT_NE(r.body.find("\"error\": \""), std::string::npos) << target << " " << r.body;
  EXPECT_NE(r.body.find(message), std::string::npos) << target << " " << r.body;
}

/// The content version the server gives world `world` (its GET /worlds/{world} document's
/// "version"), as a page that builds tile URLs reads it.
inline std::string servedVersion(std::uint16_t port, const std::string& world = "island") {
  const HttpResponse r = request(port, "/worlds/" + world);
  EXPECT_EQ(r.status, 200) << r.body;
  const std::string key = "\"version\":\"";
  const auto at = r.body.find(key);
  if (at == std::string::npos)
    return "";
  const auto from = at + key.size();
  return r.body.substr(from, r.body.find('"', from) - from);
}

/// `path` with the served world's current version (`v`), as the server's own URLs carry it.
inline std::string versioned(std::uint16_t port, const std::string& path,
                             const std::string& world = "island") {
  return path + (path.find('?') == std::string::npos ? "?v=" : "&v=") + servedVersion(port, world);
}

} // namespace strahler::app::test_support
