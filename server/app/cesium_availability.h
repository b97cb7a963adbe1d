#pragma once

#include "world_bounds.h"

#include "strahler/tiling/tile_scheme.h"

#include <cstdint>
#include <optional>
#include <string>

namespace strahler::app {

/// Which tiles of a world's geographic pyramid hold terrain, and what Cesium reads about them:
/// layer.json and the metadata extension's availability. Level 0 has both root tiles; below
/// it, the tiles that meet the box of the world's land (everything else is the ellipsoid, so
/// Cesium may draw its parent there instead of asking).
class CesiumAvailability {
public:
  /// Levels whose availability a tile's metadata carries (layer.json's metadataAvailability):
  /// tiles at levels 0, N, 2N … describe levels z + 1 … z + N below them.
  static constexpr int kMetadataLevels = 10;

  /// A rectangle of tiles of one level, TMS rows (row 0 south), inclusive.
  struct Range {
    std::int64_t startX = 0, startY = 0, endX = 0, endY = 0;
  };

  /// The availability of a world whose land spans `land`, down to `maxZoom`.
  CesiumAvailability(const LonLatBox& land, int maxZoom);

  /// The available tiles of level z (nothing past the deepest level).
  std::optional<Range> level(int z) const;
  /// True when `tile` (rows from the north, as TileId) is available.
  bool available(const geometry::TileId& tile) const;
  /// The metadata extension's JSON of `tile`: the available ranges of the kMetadataLevels
  /// levels below it among its descendants; "" when its level is not a multiple of
  /// kMetadataLevels.
  std::string metadataJson(const geometry::TileId& tile) const;
  /// layer.json: format, tiles template, version, scheme, projection, bounds, zooms,
  /// extensions, attribution, `available` for levels 0..kMetadataLevels and
  /// metadataAvailability. Its `version` is the world's content version (worldVersion()),
  /// which the tiles template carries as `?v={version}`: Cesium clients put it in every tile
  /// URL, so a regenerated world's tiles have new URLs.
  std::string layerJson(const std::string& name, const std::string& version) const;
  /// The deepest level.
  int maxZoom() const noexcept { return maxZoom_; }

private:
  LonLatBox land_;
  int maxZoom_ = 0;
};

} // namespace strahler::app
