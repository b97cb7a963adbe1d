#include "serve_command.h"

#include "cli_args.h"
#include "command_support.h"
#include "public_url.h"
#include "terminal_progress.h"
#include "tile_server.h"
#include "web_root.h"
#include "world_limits.h"
#include "world_loader.h"

#include "strahler/http/http_server.h"
#include "strahler/store/world_file.h"

#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <set>
#include <thread>

namespace strahler::app {
namespace {

/// How long SIGINT/SIGTERM lets requests in flight finish before every connection is closed.
/// Queued tile computations are dropped at once (503), so the process exits within about this
/// plus 0.3 s plus the longest single tile computation still running at the deadline;
/// docker/compose.yaml's stop_grace_period (10 s) stays above it.
constexpr std::chrono::milliseconds kDrainWindow{4000};

constexpr const char* kServeUsage =
    "usage: strahler serve [WORLD.world ...]\n"
    "                      [--coast FILE.geojson [--params FILE.json] [--seed N]\n"
    "                       [--features FILE.geojson]]\n"
    "                      [--host 127.0.0.1] [--port 8080] [--threads N] [--workers N]\n"
    "                      [--cache-mb M] [--cache-dir DIR] [--web-root DIR] [--public-url URL]\n"
    "                      [--trusted-proxies LIST]\n"
    "                      [--max-client-connections N] [--max-area-km2 N] [--max-extent-km N]\n"
    "                      [--repair] [--quiet]\n"
    "Serves worlds over HTTP: the viewer at /, TileJSON, Web Mercator and local tiles in every\n"
    "format, rivers.geojson, /health and /metrics. Without a world it loads (or generates)\n"
    "the world of --coast, or of the default island. SIGINT/SIGTERM drain and stop it.\n"
    "--cache-mb M (default 256) bounds the heap the tile cache holds; RSS stays within it plus\n"
    "the world and a few tens of MB of working memory.\n"
    "--public-url URL (http[s]://host[:port][/prefix]) is the base of absolute URLs (TileJSON's\n"
    "tiles) behind a proxy; without it they use X-Forwarded-Proto and X-Forwarded-Host from a\n"
    "trusted proxy, else the address the client connected to; never the Host header.\n"
    "--trusted-proxies LIST (default loopback): peers whose X-Forwarded-* headers are believed,\n"
    "comma-separated: loopback, none, addresses and CIDR networks (e.g. 172.16.0.0/12).\n"
    "--max-area-km2 N, --max-extent-km N: the size a --coast may have (as `strahler generate`).\n"
    "--repair: mend the --coast's topology defects and list each change (as `strahler generate`).\n"
    "--features FILE.geojson: the artist's vector map of mountains, ridges and rivers drawn on\n"
    "the --coast (as `strahler generate`); /worlds/{id}/features.geojson serves it back.\n"
    "--max-client-connections N (default 64) caps the connections of one client address (IPv6:\n"
    "one /64) among the 1,024 the server holds; at a cap the oldest idle or header-incomplete\n"
    "connection is closed to make room, else the new one gets 503. 0: no per-client cap (behind\n"
    "a proxy, whose address every connection has). A header not complete in 10 s gets 408.\n"
    "SIGINT/SIGTERM: queued tiles get 503, tiles being computed are sent, and the process\n"
    "exits within the 4 s drain window (plus the longest tile still being computed).\n";

/// A URL-safe world id from a name: [A-Za-z0-9_-], unique among `taken`.
std::string worldId(const std::string& name, std::set<std::string>& taken) {
  std::string id;
  for (char c : name)
    id += (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_') ? c : '-';
  if (id.empty())
    id = "world";
  std::string unique = id;
  for (int n = 2; taken.count(unique); ++n)
    unique = id + "-" + std::to_string(n);
  taken.insert(unique);
  return unique;
}

base::Result<std::vector<std::pair<std::string, construction::WorldData>>>
loadWorlds(const CliArgs& args) {
  std::vector<std::pair<std::string, construction::WorldData>> worlds;
  std::set<std::string> taken;
  for (const std::string& path : args.positional()) {
    STRAHLER_ASSIGN_OR_RETURN(
        construction::WorldData data,
        readWorldArgument(path, "serve a coastline with 'strahler serve --coast " + path + "'"));
    worlds.emplace_back(worldId(std::filesystem::path(path).stem().string(), taken),
                        std::move(data));
  }
  if (!worlds.empty() && !args.get("--coast") && !args.get("--features"))
    return worlds;
  auto seed = args.getU64("--seed");
  if (!seed)
    return seed.error();
  input::WorldSources sources;
  sources.coastPath = args.get("--coast").value_or("");
  sources.paramsPath = args.get("--params").value_or("");
  sources.featuresPath = args.get("--features").value_or("");
  sources.seed = seed.value();
  sources.repair = args.has("--repair");
  STRAHLER_ASSIGN_OR_RETURN(const input::InputLimits limits, worldLimits(args));
  STRAHLER_ASSIGN_OR_RETURN(input::WorldSpec spec, input::loadWorldSpec(sources, limits));
  printRepairsAndWarnings(spec);
  TerminalProgress progress(args.has("--quiet"));
  STRAHLER_ASSIGN_OR_RETURN(LoadedWorld loaded,
                            loadOrGenerateWorld(spec,
                                                args.get("--cache-dir").value_or(defaultCacheDir()),
                                                progress.callback(), nullptr));
  for (const std::string& warning : loaded.warnings)
    std::fprintf(stderr, "strahler: warning: %s\n", warning.c_str());
  worlds.emplace_back(worldId(spec.name, taken), std::move(loaded.data));
  return worlds;
}

} // namespace

int runServe(const std::vector<std::string>& raw) {
  auto parsed = CliArgs::parse("serve", raw,
                               {"--coast", "--params", "--features", "--seed", "--host", "--port",
                                "--threads", "--workers", "--cache-mb", "--cache-dir", "--web-root",
                                "--public-url", "--trusted-proxies", "--max-client-connections",
                                kMaxAreaOption, kMaxExtentOption},
                               {"--quiet", "--repair", "--help", "-h"});
  if (!parsed)
    return usageError(parsed.error(), "serve");
  const CliArgs& args = parsed.value();
  if (args.has("--help") || args.has("-h"))
    return printUsage(kServeUsage);
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  auto port = args.getInt("--port", 0, 65535);
  auto threads = args.getInt("--threads", 1, 64);
  auto workers = args.getInt("--workers", 1, 256);
  auto cacheMb = args.getInt("--cache-mb", 1, 1 << 20);
  auto perClient = args.getInt("--max-client-connections", 0, 1 << 20);
  for (const auto* r : {&port, &threads, &workers, &cacheMb, &perClient})
    if (!*r)
      return usageError(r->error(), "serve");
  if (auto seed = args.getU64("--seed"); !seed)
    return usageError(seed.error(), "serve");
  if (auto limits = worldLimits(args); !limits)
    return usageError(limits.error(), "serve");
  std::string publicUrl;
  if (const auto url = args.get("--public-url")) {
    auto checked = parsePublicUrl(*url);
    if (!checked)
      return usageError(checked.error(), "serve");
    publicUrl = std::move(checked).value();
  }
  auto trustedProxies =
      http::TrustedProxies::parse(args.get("--trusted-proxies").value_or("loopback"));
  if (!trustedProxies)
    return usageError(base::makeError(base::ErrorCode::kInvalidInput,
                                      "--trusted-proxies: " + trustedProxies.error().message),
                      "serve");

  // Block the stop signals in every thread; the main thread waits for them below.
  sigset_t stopSignals;
  sigemptyset(&stopSignals);
  sigaddset(&stopSignals, SIGINT);
  sigaddset(&stopSignals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stopSignals, nullptr);

  // Temporaries of generations killed mid-write (kill -9, OOM, power loss) would stay forever.
  const std::string cacheDir = args.get("--cache-dir").value_or(defaultCacheDir());
  if (const std::size_t stale = store::removeStaleWorldTemporaries(cacheDir); stale > 0)
    std::fprintf(stderr, "strahler: removed %zu stale temporary world file(s) from '%s'\n", stale,
                 cacheDir.c_str());
  auto worlds = loadWorlds(args);
  if (!worlds)
    return fail(worlds.error());
  TileServerOptions options;
  options.workers = static_cast<int>(workers.value().value_or(cores));
  options.cacheBytes = static_cast<std::size_t>(cacheMb.value().value_or(256)) << 20;
  options.webRoot = findWebRoot(args.get("--web-root"));
  options.publicUrl = publicUrl;
  TileServer tiles(std::move(worlds).value(), options);

  http::ServerOptions http;
  http.host = args.get("--host").value_or("127.0.0.1");
  http.port = static_cast<std::uint16_t>(port.value().value_or(8080));
  http.ioThreads = static_cast<int>(threads.value().value_or(cores));
  http.accessLog = !args.has("--quiet");
  http.trustedProxies = std::move(trustedProxies).value();
  if (perClient.value())
    http.maxConnectionsPerClient = static_cast<std::size_t>(*perClient.value());
  http::Server server(
      http,
      [&tiles](const http::Request& r, std::function<void(http::Response)> done) {
        tiles.handle(r, std::move(done));
      },
      [&tiles](const std::string& route, int status, std::size_t bytes, double ms) {
        tiles.observe(route, status, bytes, ms);
      });
  if (auto started = server.start(); !started)
    return fail(started.error());
  std::string ids;
  for (const std::string& id : tiles.worldIds())
    ids += (ids.empty() ? "" : ", ") + id;
  std::printf("strahler: serving %s at http://%s:%u/\n", ids.c_str(), http.host.c_str(),
              server.port());
  std::fflush(stdout);

  int signal = 0;
  sigwait(&stopSignals, &signal);
  std::printf("strahler: %s received, draining\n", signal == SIGTERM ? "SIGTERM" : "SIGINT");
  std::fflush(stdout);
  // Nobody would receive the queued tiles: drop them first (503, Retry-After), so that only
  // the computations already running delay the exit.
  tiles.cancelQueued();
  server.stop(kDrainWindow);
  tiles.drain();
  return 0;
}

} // namespace strahler::app
