#pragma once

#include "strahler/construction/world_data.h"

#include <string>
#include <string_view>

namespace strahler::app {

/// The content version of a world: 16 hex digits of FNV-1a 64 over its world file's bytes
/// (store::encodeWorld, which is what `generate` writes and `serve` reads back bit for bit).
/// Any change of the world's content gives another version: another generator version (it is
/// in the file), seed, coastline, parameters or drawn features, even under the same file name.
/// Every tile URL a client is told to fetch carries it as `?v=`, so a tile URL names one
/// content for ever (Cache-Control: immutable) and the ETags change with it.
std::string worldVersion(const construction::WorldData& world);

/// 16 hex digits of FNV-1a 64 over `bytes` (worldVersion() of a world file read as bytes).
std::string contentVersion(std::string_view bytes);

} // namespace strahler::app
