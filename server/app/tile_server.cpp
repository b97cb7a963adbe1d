#include "tile_server.h"

#include "cesium_availability.h"
#include "cesium_route.h"
#include "content_encoding.h"
#include "layer_route.h"
#include "public_url.h"
#include "rivers_response.h"
#include "router.h"
#include "server_gauges.h"
#include "static_files.h"
#include "tile_request.h"
#include "tile_response.h"
#include "tile_route.h"
#include "tile_service.h"
#include "vector_layers.h"
#include "web_tile_route.h"
#include "world_bounds.h"
#include "world_documents.h"
#include "world_version.h"

#include <future>
#include <utility>

namespace strahler::app {
namespace {

http::Response jsonResponse(std::string body, const std::string& route) {
  http::Response r;
  r.headers = {{"Content-Type", "application/json"}, {"Cache-Control", "no-cache"}};
  r.body = std::move(body);
  r.route = route;
  return r;
}

/// The tile that `target` asks for, read by the route parser of its tile endpoint.
base::Result<TileRequest> parseTileEndpoint(Endpoint endpoint, const std::string& world,
                                            const ParsedTarget& target,
                                            const http::Request& request) {
  switch (endpoint) {
  case Endpoint::kLayerTile:
    return parseLayerRoute(world, target.segments, target.query);
  case Endpoint::kCesiumTerrain:
    return parseCesiumTerrainRoute(world, target.segments, target.query, request.header("accept"),
                                   request.header("accept-encoding"));
  case Endpoint::kVectorTile:
    return parseVectorTileRoute(world, target.segments, target.query,
                                request.header("accept-encoding"));
  case Endpoint::kVegetationTile:
    return parseVegetationRoute(world, target.segments, target.query,
                                request.header("accept-encoding"));
  default:
    return parseTileRoute(world, target.segments, target.query);
  }
}

} // namespace

struct TileServer::ServedWorld {
  std::string id;
  std::unique_ptr<TileService> tiles;
  std::string metadata;    ///< worldMetadataJson().
  std::string cesiumLayer; ///< Its Cesium terrain's layer.json.
  std::string features;    ///< featuresGeoJson(): the artist's vector map.
  /// rivers.geojson, being written from the start (writeRiversAsync). Declared after `tiles`,
  /// whose world it reads.
  std::shared_future<RiversText> rivers;
  /// The world's content version (worldVersion()): in every tile URL handed out, and part of
  /// every ETag.
  std::string version;
  LonLatBox bounds;
  geometry::Vec2 center;
};

TileServer::TileServer(std::vector<std::pair<std::string, construction::WorldData>> worlds,
                       TileServerOptions options)
    : options_(std::move(options)), cache_(options_.cacheBytes), trimmer_(options_.trimPeriod),
      pool_(options_.workers, options_.maxQueued) {
  for (auto& [id, data] : worlds) {
    auto w = std::make_unique<ServedWorld>();
    w->id = id;
    w->tiles = std::make_unique<TileService>(std::move(data));
    const construction::WorldData& served = w->tiles->world().data();
    w->version = worldVersion(served);
    w->bounds = worldBounds(served);
    w->center = served.projectionCenter;
    w->metadata =
        worldMetadataJson(id, served, w->tiles->scheme(tiling::SchemeKind::kLocal), w->version);
    w->rivers = writeRiversAsync(served);
    w->features = featuresGeoJson(served.features);
    w->cesiumLayer =
        CesiumAvailability(w->bounds, w->tiles->scheme(tiling::SchemeKind::kGeographic).maxZoom())
            .layerJson(id, w->version);
    worlds_.push_back(std::move(w));
  }
}

TileServer::~TileServer() {
  pool_.drain();
}

void TileServer::drain() {
  pool_.drain();
}

void TileServer::cancelQueued() {
  pool_.cancelQueued();
}

std::vector<std::string> TileServer::worldIds() const {
  std::vector<std::string> ids;
  for (const auto& w : worlds_)
    ids.push_back(w->id);
  return ids;
}

const TileServer::ServedWorld* TileServer::find(const std::string& id) const {
  for (const auto& w : worlds_)
    if (w->id == id)
      return w.get();
  return nullptr;
}

void TileServer::observe(const std::string& route, int status, std::size_t, double ms) {
  metrics_.recordRequest(route, status, ms);
}

http::Response TileServer::metricsResponse() const {
  http::Response r;
  r.headers = {{"Content-Type", "text/plain; version=0.0.4"}, {"Cache-Control", "no-store"}};
  r.body = metrics_.render(
      renderWorkGauges({cache_.stats(), cache_.maxBytes(), pool_.queued(), pool_.running()}));
  r.route = "metrics";
  return r;
}

http::Response TileServer::tileJson(const ServedWorld& w, const http::Request& request,
                                    const LayerOptions* layer) const {
  // Absolute URLs (TileJSON 3.0.0 wants them, and MapLibre fetches relative ones from a
  // worker, where they fail), never from the Host header: see requestOrigin().
  const auto origin = requestOrigin(options_.publicUrl, request);
  if (!origin)
    return http::errorResponse(400, origin.error().message);
  const std::string base = origin.value() + "/worlds/" + w.id;
  http::Response r = jsonResponse(
      layer ? layerTileJson(w.id, base, kLayerNames[static_cast<std::size_t>(layer->name)],
                            layerQuery(*layer), layerDescription(layer->name), w.bounds, w.center,
                            w.version)
            : app::tileJson(w.id, base, w.bounds, w.center, w.version),
      "tilejson");
  if (options_.publicUrl.empty()) // the URLs depend on these headers (from a trusted proxy)
    r.headers.emplace_back("Vary", "X-Forwarded-Proto, X-Forwarded-Host");
  return r;
}

void TileServer::handle(const http::Request& request, std::function<void(http::Response)> done) {
  auto parsed = parseTarget(request.target);
  if (!parsed)
    return done(http::errorResponse(400, parsed.error().message));
  const ParsedTarget& target = parsed.value();
  if (target.trailingSlash) // one spelling per resource: "…/389.png/" is not "…/389.png"
    return done(http::errorResponse(
        404, "no such resource: '" +
                 request.target.substr(0, request.target.find('?')).substr(0, 200) +
                 "' ends with '/'; resources are named without it"));
  const Route route = routeOf(target.segments);
  switch (route.endpoint) {
  case Endpoint::kIndex:
    return done(indexPage(options_.webRoot, worldIds()));
  case Endpoint::kGame:
    return done(staticFile(options_.webRoot, {"game.html"}));
  case Endpoint::kCesium:
    return done(staticFile(options_.webRoot, {"cesium.html"}));
  case Endpoint::kHealth:
    return done(jsonResponse(healthJson(worlds_.size()), "health"));
  case Endpoint::kMetrics:
    return done(metricsResponse());
  case Endpoint::kWorldList: {
    std::vector<const std::string*> metadata;
    for (const auto& w : worlds_)
      metadata.push_back(&w->metadata);
    return done(jsonResponse(worldListJson(metadata), "worlds"));
  }
  case Endpoint::kStaticFile:
    return done(staticFile(options_.webRoot, target.segments));
  default:
    break;
  }
  const ServedWorld* w = find(route.world);
  if (!w)
    return done(http::errorResponse(404, "unknown world '" + route.world.substr(0, 64) + "'"));
  handleWorld(*w, route.endpoint, target, request, std::move(done));
}

void TileServer::handleWorld(const ServedWorld& w, Endpoint endpoint, const ParsedTarget& target,
                             const http::Request& request,
                             std::function<void(http::Response)> done) {
  switch (endpoint) {
  case Endpoint::kWorld:
    return done(jsonResponse(w.metadata, "world"));
  case Endpoint::kTileJson:
    return done(tileJson(w, request));
  case Endpoint::kRivers: {
    // Cached as the tiles are: immutable by the current version's URL only, and an ETag of
    // the content (and encoding), so a regenerated world's rivers never answer an old one.
    const auto v = target.query.find("v");
    RiversRequest rivers{acceptsGzip(request.header("accept-encoding")),
                         {},
                         v != target.query.end() && v->second == w.version};
    rivers.etag = tileEtag(w.version, rivers.gzip ? "rivers|gz" : "rivers|id");
    if (etagMatches(request.header("if-none-match"), rivers.etag)) {
      http::Response r = notModified(rivers.etag, "Accept-Encoding", rivers.currentVersion);
      r.route = "rivers";
      return done(std::move(r));
    }
    return answerRivers(w.rivers, rivers, pool_, std::move(done));
  }
  case Endpoint::kFeatures: {
    http::Response r;
    r.headers = {{"Content-Type", "application/geo+json"}, {"Cache-Control", "no-cache"}};
    r.body = w.features;
    r.route = "features";
    return done(std::move(r));
  }
  case Endpoint::kTile:
  case Endpoint::kLayerTile:
  case Endpoint::kCesiumTerrain:
  case Endpoint::kVectorTile:
  case Endpoint::kVegetationTile: {
    // Every kind of tile: its route's parser, then the one pipeline. An unknown layer or
    // species is 404; any other refusal of the route is 400. The world's version (`v`) is
    // not the tile's: taken out before the parser, it decides only the Cache-Control.
    ParsedTarget route = target;
    const auto v = route.query.find("v");
    const bool currentVersion = v != route.query.end() && v->second == w.version;
    if (v != route.query.end())
      route.query.erase(v);
    auto parsed = parseTileEndpoint(endpoint, w.id, route, request);
    if (!parsed)
      return done(http::errorResponse(parsed.error().code == base::ErrorCode::kNotFound ? 404 : 400,
                                      parsed.error().message));
    return tile(w, parsed.value(), request, currentVersion, std::move(done));
  }
  case Endpoint::kCesiumLayer:
    return done(jsonResponse(w.cesiumLayer, "cesium"));
  case Endpoint::kLayerTileJson: {
    if (target.query.count("size"))
      return done(http::errorResponse(400, "a layer's TileJSON takes the layer's parameters, "
                                           "not size"));
    auto layer = parseLayerOptions(target.segments[3], target.query);
    if (!layer)
      return done(http::errorResponse(layer.error().code == base::ErrorCode::kNotFound ? 404 : 400,
                                      layer.error().message));
    return done(tileJson(w, request, &layer.value()));
  }
  case Endpoint::kVectorTileJson: {
    const auto origin = requestOrigin(options_.publicUrl, request);
    if (!origin)
      return done(http::errorResponse(400, origin.error().message));
    http::Response r = jsonResponse(vectorTileJson(w.id, origin.value() + "/worlds/" + w.id,
                                                   w.bounds.west, w.bounds.south, w.bounds.east,
                                                   w.bounds.north, w.center, w.version),
                                    "tilejson");
    if (options_.publicUrl.empty()) // as tileJson(): the URLs depend on these headers
      r.headers.emplace_back("Vary", "X-Forwarded-Proto, X-Forwarded-Host");
    return done(std::move(r));
  }
  default:
    return done(http::errorResponse(404, "no such resource under /worlds/" + w.id));
  }
}

void TileServer::tile(const ServedWorld& w, const TileRequest& tile, const http::Request& request,
                      bool currentVersion, std::function<void(http::Response)> done) {
  auto checked = w.tiles->checkTile(tile);
  if (!checked) {
    // Refused before any work: labelled "error" in the metrics, as the router's refusals are.
    http::Response r = tileResponse(
        {nullptr, renderStatus(checked.error().code), std::string(checked.error().message)});
    r.route = "error";
    return done(std::move(r));
  }
  const std::string key = tileKey(tile);
  // Cesium terrain's bytes follow the Accept header (its extensions) and Accept-Encoding.
  const char* vary = tile.kind() == TileKind::kTerrain ? "Accept, Accept-Encoding"
                     : tile.kind() == TileKind::kVector || tile.kind() == TileKind::kVegetation
                         ? "Accept-Encoding"
                         : "";
  if (const std::string ifNoneMatch = request.header("if-none-match"); !ifNoneMatch.empty()) {
    const std::string etag = tileEtag(w.version, key);
    if (etagMatches(ifNoneMatch, etag))
      return done(notModified(etag, vary, currentVersion));
  }
  if (auto hit = cache_.find(key))
    return done(tileResponse({std::move(hit), service::TileStatus::kOk, {}}, currentVersion));
  const TileService* service = w.tiles.get();
  // The tile was checked once, above; the worker renders it without checking it again.
  auto compute = [this, service, checked = std::move(checked).value(), vary,
                  etag = tileEtag(w.version, key)]() {
    auto rendered = service->render(checked);
    trimmer_.noteActivity();
    if (!rendered)
      return service::TileCache::Outcome{nullptr, renderStatus(rendered.error().code),
                                         rendered.error().message};
    metrics_.recordTile(rendered.value().evaluateMs, rendered.value().encodeMs);
    return service::TileCache::Outcome{
        cachedTile(std::move(rendered).value(), etag, vary), service::TileStatus::kOk, {}};
  };
  cache_.get(
      key, compute, [this](std::function<void()> work) { return pool_.submit(std::move(work)); },
      [done = std::move(done), currentVersion](const service::TileCache::Outcome& outcome) {
        done(tileResponse(outcome, currentVersion));
      },
      request.clientGone);
}

} // namespace strahler::app
