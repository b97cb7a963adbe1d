#include "static_files.h"

#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>

namespace strahler::app {
namespace {

const char* staticMime(const std::string& ext) {
  static const std::map<std::string, const char*> kTypes = {{".html", "text/html; charset=utf-8"},
                                                            {".js", "text/javascript"},
                                                            {".mjs", "text/javascript"},
                                                            {".css", "text/css"},
                                                            {".json", "application/json"},
                                                            {".png", "image/png"},
                                                            {".jpg", "image/jpeg"},
                                                            {".svg", "image/svg+xml"},
                                                            {".wasm", "application/wasm"},
                                                            {".map", "application/json"},
                                                            {".ico", "image/x-icon"}};
  const auto it = kTypes.find(ext);
  return it == kTypes.end() ? nullptr : it->second;
}

} // namespace

http::Response staticFile(const std::string& webRoot, const std::vector<std::string>& segments) {
  if (!webRoot.empty()) {
    std::filesystem::path file(webRoot);
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

http::Response indexPage(const std::string& webRoot, const std::vector<std::string>& worldIds) {
  if (!webRoot.empty()) {
    std::ifstream in(std::filesystem::path(webRoot) / "index.html", std::ios::binary);
    if (in) {
      http::Response r;
      r.headers = {{"Content-Type", "text/html; charset=utf-8"}, {"Cache-Control", "no-cache"}};
      r.body.assign(std::istreambuf_iterator<char>(in), {});
      r.route = "viewer";
      return r;
    }
  }
  std::string list;
  for (const std::string& id : worldIds)
    list += "<li><b>" + id + "</b>: <a href=\"/worlds/" + id +
            "\">metadata</a>, <a href=\"/worlds/" + id +
            "/tilejson.json\">TileJSON</a>, <a href=\"/worlds/" + id +
            "/rivers.geojson\">rivers</a>, <a href=\"/worlds/" + id +
            "/local/0/0/0.png\">local tile 0/0/0</a></li>";
  http::Response r;
  r.headers = {{"Content-Type", "text/html; charset=utf-8"}, {"Cache-Control", "no-cache"}};
  r.body = "<!doctype html><html><head><meta charset=\"utf-8\"><title>strahler</title></head><body>"
           "<h1>strahler tile server</h1><p>Worlds:</p><ul>" +
           list +
           "</ul><p>Tiles: "
           "<code>/worlds/{id}/tiles/{z}/{x}/{y}.{png|png16|tif|exr|drc|glb|relief}</code> "
           "(Web Mercator), "
           "<code>/worlds/{id}/local/{z}/{x}/{y}.{ext}</code> (local quadtree). "
           "<a href=\"/health\">health</a>, <a href=\"/metrics\">metrics</a>.</p></body></html>";
  r.route = "viewer";
  return r;
}

} // namespace strahler::app
