// libFuzzer harness: the bytes a client sends on one connection, handled as
// server/http/src/session.cpp handles them: Beast's header parser with the server's limits, the
// protocol rules (checkRequest / checkParseError), the response as written (toWireResponse,
// appendHead), and for forwarded requests the router (parseTarget, routeOf) and the tile route
// parsers as TileServer dispatches them (the world version `v` taken out first):
// parseTileRoute, parseCesiumTerrainRoute (with the Accept and Accept-Encoding headers and
// ?extensions=), parseLayerRoute, parseVectorTileRoute, parseVegetationRoute; with JSON error
// answers quoting the client's bytes. Pipelined requests are followed while the
// connection would stay open. (The tile server itself needs a world and the terrain code:
// tests/app covers its dispatch.)
#include "cesium_route.h"
#include "layer_route.h"
#include "request_rules.h"
#include "route_parser.h"
#include "router.h"
#include "tile_route.h"
#include "web_tile_route.h"
#include "wire_response.h"

#include <boost/asio/buffer.hpp>

#include <cstdint>
#include <cstdlib>
#include <limits>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace {

using namespace strahler::http::detail;

/// Pipelined requests followed per input, as a session's queue allows.
constexpr int kMaxRequests = 16;

/// Writes `response` as the session would; aborts (a crash for libFuzzer) on a broken head.
void writeResponse(strahler::http::Response response, unsigned version, bool head, bool keepAlive) {
  const WireResponse wire = toWireResponse(std::move(response), version, head);
  std::string out;
  appendHead(out, wire, keepAlive, "Thu, 01 Jan 1970 00:00:00 GMT");
  if (wire.status < 200 || wire.status > 599 || out.size() < 4 ||
      out.compare(out.size() - 4, 4, "\r\n\r\n") != 0 || out.find("\r\n\r\n") != out.size() - 4)
    std::abort();
}

/// The tile `target` names, read by its endpoint's parser as TileServer::handleWorld does.
strahler::base::Result<strahler::app::TileRequest>
parseTile(strahler::app::Endpoint endpoint, const std::string& world,
          const strahler::app::ParsedTarget& target, const strahler::http::Request& request) {
  using strahler::app::Endpoint;
  std::map<std::string, std::string> query = target.query;
  query.erase("v"); // the world's version: not the tile's
  const auto& s = target.segments;
  switch (endpoint) {
  case Endpoint::kLayerTile:
    return strahler::app::parseLayerRoute(world, s, query);
  case Endpoint::kCesiumTerrain:
    return strahler::app::parseCesiumTerrainRoute(world, s, query, request.header("accept"),
                                                  request.header("accept-encoding"));
  case Endpoint::kVectorTile:
    return strahler::app::parseVectorTileRoute(world, s, query, request.header("accept-encoding"));
  case Endpoint::kVegetationTile:
    return strahler::app::parseVegetationRoute(world, s, query, request.header("accept-encoding"));
  default:
    return strahler::app::parseTileRoute(world, s, query);
  }
}

/// The router's parsing of a forwarded request, answered as a server without worlds would
/// (tile routes parsed in full first); true when the answer closes the connection.
bool route(const strahler::http::Request& request, unsigned version, bool keepAlive) {
  using strahler::app::Endpoint;
  strahler::http::Response response;
  const auto parsed = strahler::app::parseTarget(request.target);
  const auto route =
      parsed ? strahler::app::routeOf(parsed.value().segments) : strahler::app::Route{};
  const bool tileEndpoint =
      route.endpoint == Endpoint::kTile || route.endpoint == Endpoint::kLayerTile ||
      route.endpoint == Endpoint::kCesiumTerrain || route.endpoint == Endpoint::kVectorTile ||
      route.endpoint == Endpoint::kVegetationTile;
  const auto& s = parsed ? parsed.value().segments : std::vector<std::string>{};
  if (!parsed) {
    response = strahler::http::errorResponse(400, parsed.error().message);
    response.close = true;
  } else if (tileEndpoint) {
    const auto tile = parseTile(route.endpoint, route.world, parsed.value(), request);
    if (!tile) {
      response = strahler::http::errorResponse(400, tile.error().message);
      response.close = true;
    } else {
      response.headers = {{"Content-Type", "application/octet-stream"},
                          {"X-Tile-Key", strahler::app::tileKey(tile.value())}}; // client bytes
      response.body = strahler::app::canonicalFormatName(tile.value().format);
    }
  } else if (s.size() >= 2 && s[0] == "worlds") {
    response = strahler::http::errorResponse(404, "unknown world '" + s[1].substr(0, 64) + "'");
  } else {
    response = strahler::http::errorResponse(404, "not found");
  }
  const bool close = response.close;
  writeResponse(std::move(response), version, request.head, keepAlive && !close);
  return close;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const strahler::http::ServerOptions options; // the production limits
  std::string_view input(reinterpret_cast<const char*>(data), size);
  for (int n = 0; n < kMaxRequests && !input.empty(); ++n) {
    RequestParser parser;
    parser.header_limit(static_cast<std::uint32_t>(options.maxHeaderBytes));
    parser.body_limit(std::numeric_limits<std::uint64_t>::max());
    ErrorCode ec;
    const std::size_t used = parser.put(boost::asio::buffer(input.data(), input.size()), ec);
    if (ec == boost::beast::http::error::need_more)
      return 0; // the rest never comes: the connection ends without an answer
    if (ec) {
      if (!isParseError(ec))
        return 0;
      const Verdict verdict = checkParseError(ec, parser, input.substr(used), options);
      if (verdict.kind != Verdict::Kind::kReject || !verdict.close)
        std::abort(); // a parse error is always answered and closes
      writeResponse(verdict.response, 11, false, false);
      return 0;
    }
    if (!parser.is_header_done())
      return 0;
    input.remove_prefix(used);
    const auto& header = parser.get();
    const Verdict verdict = checkRequest(parser, options);
    const bool head = header.method() == boost::beast::http::verb::head;
    bool keepAlive = header.keep_alive() && !verdict.close;
    const unsigned version = header.version() == 10 ? 10 : 11;
    if (verdict.kind == Verdict::Kind::kForward)
      keepAlive =
          !route(makeRequest(header, head, "127.0.0.1:8080", false, nullptr), version, keepAlive) &&
          keepAlive;
    else
      writeResponse(verdict.response, version, head, keepAlive);
    if (!keepAlive)
      return 0;
  }
  return 0;
}
