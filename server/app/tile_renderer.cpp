#include "tile_renderer.h"

#include "gzip.h"

namespace strahler::app {

void gzipIfAsked(const TileRequest& request, RenderedTile& out) {
  if (!request.options.gzip)
    return;
  const auto start = RenderClock::now();
  out.bytes = gzip::compress(out.bytes, gzip::Level::kFastest);
  out.contentEncoding = "gzip";
  out.encodeMs += millisecondsSince(start);
}

} // namespace strahler::app
