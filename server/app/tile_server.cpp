#include "tile_server.h"

#include "content_encoding.h"
#include "gzip.h"
#include "public_url.h"
#include "route_parser.h"
#include "tile_route.h"
#include "world_bounds.h"

#include "strahler/render/rivers_geojson.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <future>
#include <sstream>
#include <utility>

namespace strahler::app {
namespace {

using nlohmann::json;

constexpr const char* kTileCacheControl = "public, max-age=86400, immutable";
constexpr int kTileJsonMaxZoom = 16; // DEM detail advertised; deeper tiles are still served

constexpr std::uint64_t kFnvOffset = 1469598103934665603ull;

/// FNV-1a of `text`, continuing from `h` (so that hashing parts equals hashing their concat).
std::uint64_t fnv1a(std::string_view text, std::uint64_t h = kFnvOffset) {
  for (unsigned char c : text)
    h = (h ^ c) * 1099511628211ull;
  return h;
}

/// The strong ETag of a tile: "\"" + 16 hex digits of fnv1a(worldKey|tileKey) + "\"".
std::string tileEtag(const std::string& worldKey, const std::string& tileKey) {
  std::uint64_t h = fnv1a(tileKey, fnv1a("|", fnv1a(worldKey)));
  std::string etag(18, '"');
  for (int i = 16; i >= 1; --i, h >>= 4)
    etag[static_cast<std::size_t>(i)] = "0123456789abcdef"[h & 0xF];
  return etag;
}

/// The status of a tile that could not be made: 404 for what does not exist, 501 for a format
/// this installation cannot make (its OpenImageIO module is missing), 500 for the rest.
int tileErrorStatus(base::ErrorCode code) {
  switch (code) {
  case base::ErrorCode::kNotFound:
    return 404;
  case base::ErrorCode::kUnsupported:
    return 501;
  default:
    return 500;
  }
}

/// Header fields of a tile's 200 response.
std::vector<std::pair<std::string, std::string>> tileHeaders(const service::CachedTile& t) {
  return {{"Content-Type", t.mimeType},
          {"ETag", t.etag},
          {"Cache-Control", kTileCacheControl},
          {"Server-Timing", "eval;dur=" + std::to_string(t.evaluateMs) +
                                ", encode;dur=" + std::to_string(t.encodeMs)}};
}

/// The 200 response carrying `tile`: its bytes and prepared header fields alias the cached
/// tile, so a cache hit formats and copies nothing.
http::Response tileResponse(const std::shared_ptr<const service::CachedTile>& tile) {
  http::Response r;
  r.sharedBody = std::shared_ptr<const std::string>(tile, &tile->bytes);
  if (tile->httpFields.empty()) {
    r.headers = tileHeaders(*tile);
  } else {
    r.preparedFields = std::shared_ptr<const std::string>(tile, &tile->httpFields);
  }
  r.route = "tile";
  return r;
}

http::Response jsonResponse(const json& body, const std::string& route) {
  http::Response r;
  r.headers = {{"Content-Type", "application/json"}, {"Cache-Control", "no-cache"}};
  r.body = body.dump();
  r.route = route;
  return r;
}

bool etagMatches(const std::string& ifNoneMatch, const std::string& etag) {
  if (ifNoneMatch.empty())
    return false;
  if (ifNoneMatch == "*")
    return true;
  std::stringstream list(ifNoneMatch);
  std::string item;
  while (std::getline(list, item, ',')) {
    const auto b = item.find_first_not_of(" \t");
    const auto e = item.find_last_not_of(" \t");
    if (b != std::string::npos && item.substr(b, e - b + 1) == etag)
      return true;
  }
  return false;
}

const char* staticMime(const std::string& ext) {
  static const std::map<std::string, const char*> kTypes = {{".html", "text/html; charset=utf-8"},
                                                            {".js", "text/javascript"},
                                                            {".mjs", "text/javascript"},
                                                            {".css", "text/css"},
                                                            {".json", "application/json"},
                                                            {".png", "image/png"},
                                                            {".svg", "image/svg+xml"},
                                                            {".wasm", "application/wasm"},
                                                            {".map", "application/json"},
                                                            {".ico", "image/x-icon"}};
  const auto it = kTypes.find(ext);
  return it == kTypes.end() ? nullptr : it->second;
}

} // namespace

struct TileServer::ServedWorld {
  std::string id;
  std::unique_ptr<TileService> tiles;
  json metadata;
  /// rivers.geojson, written (and gzipped) on a thread of its own from the start: a large
  /// world's takes seconds, which the server does not wait for. Declared after `tiles`, whose
  /// world it reads.
  std::shared_future<RiversText> rivers;
  std::string cacheKey; // world's cache key: part of every ETag
  double bounds[4] = {0, 0, 0, 0};
  geometry::Vec2 center;
};

TileServer::TileServer(std::vector<std::pair<std::string, construction::WorldData>> worlds,
                       TileServerOptions options)
    : options_(std::move(options)), cache_(options_.cacheBytes), trimmer_(options_.trimPeriod),
      pool_(options_.workers, options_.maxQueued) {
  for (auto& [id, data] : worlds) {
    auto w = std::make_unique<ServedWorld>();
    w->id = id;
    w->cacheKey = data.cacheKey;
    const geometry::LocalProjection projection(data.projectionCenter.x, data.projectionCenter.y);
    const LonLatBox box = worldBounds(data);
    w->bounds[0] = box.west, w->bounds[1] = box.south, w->bounds[2] = box.east,
    w->bounds[3] = box.north;
    w->center = data.projectionCenter;
    w->metadata = {{"id", id},
                   {"name", data.name},
                   {"bounds", {w->bounds[0], w->bounds[1], w->bounds[2], w->bounds[3]}},
                   {"center", {w->center.x, w->center.y}},
                   {"areaKm2", data.areaKm2()},
                   {"nodes", data.network.nodes.size()},
                   {"mouths", data.network.mouths.size()},
                   {"terrainPrimitives", data.terrain.size()},
                   {"riverPrimitives", data.rivers.size()},
                   {"seed", data.params.seed},
                   {"generatorVersion", data.generatorVersion},
                   {"cacheKey", data.cacheKey}};
    w->tiles = std::make_unique<TileService>(std::move(data));
    const construction::WorldData& served = w->tiles->world().data();
    w->rivers = std::async(std::launch::async, [&served, projection] {
                  auto plain = std::make_shared<const std::string>(
                      render::riversGeoJson(served, projection));
                  return RiversText{plain, std::make_shared<const std::string>(
                                               gzip::compress(*plain, gzip::Level::kFastest))};
                }).share();
    const tiling::TileScheme& local = w->tiles->scheme(tiling::SchemeKind::kLocal);
    const geometry::Aabb root = local.localBounds({0, 0, 0});
    w->metadata["web"] = {{"minzoom", 0}, {"maxzoom", tiling::TileScheme::kMaxWebZoom}};
    w->metadata["local"] = {{"minzoom", 0},
                            {"maxzoom", local.maxZoom()},
                            {"rootSouthWest", {root.min.x, root.min.y}},
                            {"rootSide", root.size().x}};
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

std::string TileServer::gauges() const {
  const service::TileCacheStats s = cache_.stats();
  std::string g;
  auto gauge = [&](const char* name, const char* help, const char* type, double v) {
    g += std::string("# HELP ") + name + " " + help + "\n# TYPE " + name + " " + type + "\n" +
         name + " " + std::to_string(v) + "\n";
  };
  gauge("strahler_tile_cache_hits_total", "Tile cache hits.", "counter", double(s.hits));
  gauge("strahler_tile_cache_misses_total", "Tile cache misses.", "counter", double(s.misses));
  gauge("strahler_tile_cache_evictions_total", "Tiles evicted from the cache.", "counter",
        double(s.evictions));
  gauge("strahler_tile_cache_bytes", "Bytes held by the tile cache.", "gauge", double(s.bytes));
  gauge("strahler_tile_cache_max_bytes", "Byte bound of the tile cache.", "gauge",
        double(cache_.maxBytes()));
  gauge("strahler_tile_cache_entries", "Tiles held by the tile cache.", "gauge", double(s.entries));
  gauge("strahler_tiles_in_flight", "Distinct tiles being computed.", "gauge", double(s.inFlight));
  gauge("strahler_tile_computations_total", "Tiles computed (single flight: once per key).",
        "counter", double(s.computations));
  gauge("strahler_tile_requests_coalesced_total",
        "Requests that waited for a computation in flight.", "counter", double(s.coalesced));
  gauge("strahler_tile_computations_cancelled_total",
        "Queued tile computations skipped because every client of the tile had gone.", "counter",
        double(s.cancelled));
  gauge("strahler_worker_queue_depth", "Tile computations waiting for a worker.", "gauge",
        double(pool_.queued()));
  gauge("strahler_workers_busy", "Workers computing a tile.", "gauge", double(pool_.running()));
  return g;
}

http::Response TileServer::index() const {
  if (!options_.webRoot.empty()) {
    std::ifstream in(std::filesystem::path(options_.webRoot) / "index.html", std::ios::binary);
    if (in) {
      http::Response r;
      r.headers = {{"Content-Type", "text/html; charset=utf-8"}, {"Cache-Control", "no-cache"}};
      r.body.assign(std::istreambuf_iterator<char>(in), {});
      r.route = "viewer";
      return r;
    }
  }
  std::string list;
  for (const auto& w : worlds_)
    list += "<li><b>" + w->id + "</b>: <a href=\"/worlds/" + w->id +
            "\">metadata</a>, <a href=\"/worlds/" + w->id +
            "/tilejson.json\">TileJSON</a>, <a href=\"/worlds/" + w->id +
            "/rivers.geojson\">rivers</a>, <a href=\"/worlds/" + w->id +
            "/local/0/0/0.png\">local tile 0/0/0</a></li>";
  http::Response r;
  r.headers = {{"Content-Type", "text/html; charset=utf-8"}, {"Cache-Control", "no-cache"}};
  r.body = "<!doctype html><html><head><meta charset=\"utf-8\"><title>strahler</title></head><body>"
           "<h1>strahler tile server</h1><p>Worlds:</p><ul>" +
           list +
           "</ul><p>Tiles: <code>/worlds/{id}/tiles/{z}/{x}/{y}.{png|png16|tif|exr|drc|glb}</code> "
           "(Web Mercator), "
           "<code>/worlds/{id}/local/{z}/{x}/{y}.{ext}</code> (local quadtree). "
           "<a href=\"/health\">health</a>, <a href=\"/metrics\">metrics</a>.</p></body></html>";
  r.route = "viewer";
  return r;
}

http::Response TileServer::worldList(const http::Request&) const {
  json list = json::array();
  for (const auto& w : worlds_)
    list.push_back(w->metadata);
  return jsonResponse(list, "worlds");
}

http::Response TileServer::tileJson(const ServedWorld& w, const http::Request& request) const {
  // Absolute URLs (TileJSON 3.0.0 wants them, and MapLibre fetches relative ones from a
  // worker, where they fail), never from the Host header: see requestOrigin().
  const auto origin = requestOrigin(options_.publicUrl, request);
  if (!origin)
    return http::errorResponse(400, origin.error().message);
  const std::string base = origin.value() + "/worlds/" + w.id;
  const json tj = {{"tilejson", "3.0.0"},
                   {"name", w.id},
                   {"description", "strahler terrain (Terrain-RGB heightmap)"},
                   {"version", "1.0.0"},
                   {"scheme", "xyz"},
                   {"tiles", {base + "/tiles/{z}/{x}/{y}.png"}},
                   {"minzoom", 0},
                   {"maxzoom", kTileJsonMaxZoom},
                   {"bounds", {w.bounds[0], w.bounds[1], w.bounds[2], w.bounds[3]}},
                   {"center", {w.center.x, w.center.y, 9}},
                   {"tileSize", 256},
                   {"encoding", "mapbox"},
                   {"attribution", "strahler"}};
  http::Response r = jsonResponse(tj, "tilejson");
  if (options_.publicUrl.empty()) // the URLs depend on these headers (from a trusted proxy)
    r.headers.emplace_back("Vary", "X-Forwarded-Proto, X-Forwarded-Host");
  return r;
}

void TileServer::handle(const http::Request& request, std::function<void(http::Response)> done) {
  auto parsed = parseTarget(request.target);
  if (!parsed)
    return done(http::errorResponse(400, parsed.error().message));
  const std::vector<std::string>& s = parsed.value().segments;
  if (s.empty())
    return done(index());
  if (s.size() == 1 && s[0] == "game")
    return done(staticFile({"game.html"}));
  if (s.size() == 1 && s[0] == "health")
    return done(jsonResponse({{"status", "ok"}, {"worlds", worlds_.size()}}, "health"));
  if (s.size() == 1 && s[0] == "metrics") {
    http::Response r;
    r.headers = {{"Content-Type", "text/plain; version=0.0.4"}, {"Cache-Control", "no-store"}};
    r.body = metrics_.render(gauges());
    r.route = "metrics";
    return done(std::move(r));
  }
  if (s[0] == "worlds") {
    if (s.size() == 1)
      return done(worldList(request));
    const ServedWorld* w = find(s[1]);
    if (!w)
      return done(http::errorResponse(404, "unknown world '" + s[1].substr(0, 64) + "'"));
    if (s.size() == 2)
      return done(jsonResponse(w->metadata, "world"));
    if (s.size() == 3 && s[2] == "tilejson.json")
      return done(tileJson(*w, request));
    if (s.size() == 3 && s[2] == "rivers.geojson")
      return rivers(*w, request, std::move(done));
    if (s.size() == 6 && (s[2] == "tiles" || s[2] == "local"))
      return tile(*w, s, parsed.value().query, request, std::move(done));
    return done(http::errorResponse(404, "no such resource under /worlds/" + w->id));
  }
  done(staticFile(s));
}

namespace {

http::Response riversResponse(const RiversText& rivers, bool gzip) {
  http::Response r;
  r.headers = {{"Content-Type", "application/geo+json"},
               {"Cache-Control", "public, max-age=3600"},
               {"Vary", "Accept-Encoding"}};
  if (gzip)
    r.headers.emplace_back("Content-Encoding", "gzip");
  r.sharedBody = gzip ? rivers.gzip : rivers.plain;
  r.route = "rivers";
  return r;
}

/// A request for rivers.geojson waiting on a worker. Whatever becomes of the task (run,
/// refused, or dropped unrun at shutdown) the client gets one answer: the GeoJSON or a 503.
class RiversWaiter {
public:
  RiversWaiter(std::shared_future<RiversText> rivers, bool gzip,
               std::function<void(http::Response)> done)
      : rivers_(std::move(rivers)), gzip_(gzip), done_(std::move(done)) {}
  RiversWaiter(const RiversWaiter&) = delete;
  RiversWaiter& operator=(const RiversWaiter&) = delete;
  ~RiversWaiter() {
    if (!done_)
      return;
    http::Response r = http::errorResponse(503, "the rivers are still being written");
    r.headers.emplace_back("Retry-After", "1");
    r.route = "rivers";
    std::exchange(done_, nullptr)(std::move(r));
  }

  /// Waits for the GeoJSON and sends it.
  void answer() {
    http::Response r = riversResponse(rivers_.get(), gzip_); // throws: the destructor's 503
    std::exchange(done_, nullptr)(std::move(r));
  }

private:
  std::shared_future<RiversText> rivers_;
  bool gzip_ = false;
  std::function<void(http::Response)> done_;
};

} // namespace

void TileServer::rivers(const ServedWorld& world, const http::Request& request,
                        std::function<void(http::Response)> done) {
  const bool gzip = acceptsGzip(request.header("accept-encoding"));
  if (world.rivers.wait_for(std::chrono::seconds(0)) == std::future_status::ready)
    return done(riversResponse(world.rivers.get(), gzip));
  // Still being written: wait on a worker, not on this I/O thread.
  auto waiter = std::make_shared<RiversWaiter>(world.rivers, gzip, std::move(done));
  pool_.submit([waiter] { waiter->answer(); }); // refused: the waiter answers 503
}

http::Response TileServer::staticFile(const std::vector<std::string>& segments) const {
  if (!options_.webRoot.empty()) {
    std::filesystem::path file(options_.webRoot);
    for (const std::string& part : segments)
      file /= part;
    const char* mime = staticMime(file.extension().string());
    std::ifstream in(file, std::ios::binary);
    if (mime && in && std::filesystem::is_regular_file(file)) {
      http::Response r;
      r.headers = {{"Content-Type", mime}, {"Cache-Control", "public, max-age=300"}};
      r.body.assign(std::istreambuf_iterator<char>(in), {});
      r.route = "static";
      return r;
    }
  }
  return http::errorResponse(404, "not found");
}

void TileServer::tile(const ServedWorld& w, const std::vector<std::string>& s,
                      const std::map<std::string, std::string>& query, const http::Request& request,
                      std::function<void(http::Response)> done) {
  auto route = parseTileRoute(w.id, s, query);
  if (!route)
    return done(http::errorResponse(400, route.error().message));
  const TileRequest req = route.value().request;
  const std::string& key = route.value().key;
  const tiling::TileScheme& scheme = w.tiles->scheme(req.scheme);
  if (!scheme.contains(req.tile))
    return done(http::errorResponse(
        404, "tile " + std::to_string(req.tile.z) + "/" + std::to_string(req.tile.x) + "/" +
                 std::to_string(req.tile.y) + " is outside the grid (zoom 0.." +
                 std::to_string(scheme.maxZoom()) + ")"));
  if (const std::string ifNoneMatch = request.header("if-none-match"); !ifNoneMatch.empty()) {
    const std::string etag = tileEtag(w.cacheKey, key);
    if (etagMatches(ifNoneMatch, etag)) {
      http::Response r;
      r.status = 304;
      r.headers = {{"ETag", etag}, {"Cache-Control", kTileCacheControl}};
      r.route = "tile";
      return done(std::move(r));
    }
  }
  if (auto hit = cache_.find(key))
    return done(tileResponse(hit));
  const TileService* service = w.tiles.get();
  auto compute = [this, service, req, etag = tileEtag(w.cacheKey, key)]() {
    auto rendered = service->render(req);
    trimmer_.noteActivity();
    if (!rendered)
      return service::TileCache::Outcome{nullptr, tileErrorStatus(rendered.error().code),
                                         rendered.error().message};
    metrics_.recordTile(rendered.value().evaluateMs, rendered.value().encodeMs);
    auto t = std::make_shared<service::CachedTile>();
    t->bytes = std::move(rendered.value().bytes);
    t->bytes.shrink_to_fit(); // the cache charges capacity: keep no encoder reservation
    t->mimeType = rendered.value().mimeType;
    t->etag = etag;
    t->evaluateMs = rendered.value().evaluateMs;
    t->encodeMs = rendered.value().encodeMs;
    http::Response plain;
    plain.headers = tileHeaders(*t);
    plain.sharedBody = std::shared_ptr<const std::string>(t, &t->bytes);
    t->httpFields = http::prepareFields(plain);
    t->httpFields.shrink_to_fit();
    return service::TileCache::Outcome{std::move(t), 0, {}};
  };
  cache_.get(
      key, compute, [this](std::function<void()> work) { return pool_.submit(std::move(work)); },
      [done = std::move(done)](const service::TileCache::Outcome& outcome) {
        if (!outcome.tile) {
          http::Response r = http::errorResponse(outcome.errorStatus, outcome.errorMessage);
          if (outcome.errorStatus == 503)
            r.headers.emplace_back("Retry-After", "1");
          r.route = "tile";
          return done(std::move(r));
        }
        done(tileResponse(outcome.tile));
      },
      request.clientGone);
}

} // namespace strahler::app
