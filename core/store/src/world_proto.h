#pragma once

// Private to core/store (and its tests): the protobuf side of the world file.

#include "strahler/base/result.h"
#include "strahler/construction/world_data.h"
#include "strahler/v1/world.pb.h"

#include <cstdint>
#include <string>
#include <string_view>

namespace strahler::store::detail {

/// Largest |k| of a stored quantum count: 2^50, small enough that llround(k · step / step)
/// is k again, so whatever the reader accepts the writer can write back unchanged.
inline constexpr std::int64_t kMaxQuanta = std::int64_t{1} << 50;

/// The payload message of `world`; asserts the WorldData invariants.
v1::World toProto(const construction::WorldData& world);

/// Validates `message` completely, then builds the world; faults are kCorrupt messages
/// starting "world file '<name>': ".
base::Result<construction::WorldData> fromProto(const v1::World& message, std::string_view name);

/// Header (magic, `version`, payload length) + `payload` + CRC-32 of everything before it.
std::string frame(std::string_view payload, std::uint32_t version);

/// The payload of framed `bytes` after the size, magic, version, length and checksum checks.
base::Result<std::string_view> unframe(std::string_view bytes, std::string_view name);

/// A kCorrupt error "world file '<name>': <what>".
base::Error corruptError(std::string_view name, std::string_view what);

} // namespace strahler::store::detail
