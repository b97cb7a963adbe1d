#pragma once

namespace strahler::service {

/// What became of a tile request, in the tile's own terms: no transport knows of it here
/// (server/app/tile_response.h maps it to an HTTP status and header fields).
enum class TileStatus {
  kOk,          ///< The tile was made (or found cached).
  kNotFound,    ///< The tile does not exist (e.g. outside its pyramid).
  kUnsupported, ///< This installation cannot make the tile (e.g. a format module is missing).
  kRetryLater,  ///< Not made now (overload, shutdown, every requester gone); asking again may.
  kFailed,      ///< Making the tile failed.
};

} // namespace strahler::service
