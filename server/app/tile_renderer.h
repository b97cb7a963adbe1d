#pragma once

#include "render_clock.h"
#include "tile_request.h"

#include "strahler/base/result.h"
#include "strahler/tiling/tile_evaluator.h"
#include "strahler/tiling/tile_scheme.h"

#include <string>
#include <vector>

namespace strahler::app {

/// A finished tile with what it cost.
struct RenderedTile {
  std::string bytes;           ///< The encoded tile.
  std::string mimeType;        ///< Its media type (image/png, model/gltf-binary, ...).
  std::string contentEncoding; ///< "gzip" when the bytes are gzipped, else "".
  double evaluateMs = 0.0;     ///< Sampling the terrain.
  double encodeMs = 0.0;       ///< Turning the samples into bytes.
  tiling::TileStats stats;     ///< What the evaluation touched (blocks, primitives).
};

/// What a renderer reads: the world's terrain evaluator and the pyramid of the request.
struct RenderContext {
  const tiling::TileEvaluator& evaluator; ///< Heights of the world at any sample grid.
  const tiling::TileScheme& scheme;       ///< The pyramid of the request (its grids and frames).
};

/// Makes the bytes of one kind of tile (TileKind). It knows nothing of transports or caches:
/// a new kind of tile is a new renderer registered with the TileService. Thread-safe.
/// The heights of `grid` from the context's evaluator, into `out`'s evaluateMs and stats: the
/// first step of every renderer.
inline std::vector<double> evaluateGrid(const RenderContext& context,
                                        const tiling::SampleGrid& grid, RenderedTile& out) {
  const auto start = RenderClock::now();
  std::vector<double> heights = context.evaluator.evaluate(grid, &out.stats);
  out.evaluateMs = millisecondsSince(start);
  return heights;
}

/// Gzips `out`'s bytes when `request` asks for it (Content-Encoding: gzip, the fastest level),
/// adding the time to encodeMs: the last step of the renderers whose tiles travel gzipped.
void gzipIfAsked(const TileRequest& request, RenderedTile& out);

class TileRenderer {
public:
  virtual ~TileRenderer() = default;

  /// The bytes of `request` (already checked: inside the grid, its kind, `size` in range).
  virtual base::Result<RenderedTile> render(const RenderContext& context,
                                            const TileRequest& request, int size) const = 0;
};

} // namespace strahler::app
