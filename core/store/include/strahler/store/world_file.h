#pragma once

#include "strahler/base/result.h"
#include "strahler/construction/world_data.h"

#include <chrono>
#include <cstdint>
#include <string>
#include <string_view>

namespace strahler::store {

// A world file (proto/strahler/v1/world.proto holds the payload schema):
//
//   offset  size  field
//   0       14    magic "STRAHLERWORLD\0"
//   14      4     u32 file format version, little-endian (kWorldFormatVersion)
//   18      8     u64 payload length P, little-endian
//   26      P     payload: a serialised strahler.v1.World message
//   26+P    4     u32 CRC-32 (zlib's crc32) of bytes [0, 26+P), little-endian
//
// Every value is stored as an integer number of its quantum (primitives::Quantum), delta-coded
// in packed columns, so a world costs a few hundred bytes per km² and reads back bit for bit.

/// Version of the file layout and payload schema this strahler writes for a world with an
/// erosion residual (WorldData::relief); it reads it and kWorldFormatVersionWithoutRelief.
inline constexpr std::uint32_t kWorldFormatVersion = 3;
/// Version written for a world without a residual: the bytes of the strahler before erosion
/// at generation, which older readers still read.
inline constexpr std::uint32_t kWorldFormatVersionWithoutRelief = 2;
/// Bytes before the payload: magic, version, payload length.
inline constexpr std::size_t kWorldHeaderBytes = 26;
/// Bytes after the payload: the CRC-32.
inline constexpr std::size_t kWorldTrailerBytes = 4;
/// Largest world file strahler reads (1 GiB, ~40× the largest world the input limits allow);
/// larger files are refused as corrupt before they are read.
inline constexpr std::uint64_t kMaxWorldFileBytes = std::uint64_t{1} << 30;

/// The complete file bytes of `world`. Deterministic: equal worlds give equal bytes, whatever
/// their stageSeconds (timings are not stored, so fresh generations of the same inputs match).
/// Asserts the WorldData invariants (values on their quantum grid, parents before children,
/// one block per node with contiguous primitive ranges, curves of ≥ 2 points, ...).
std::string encodeWorld(const construction::WorldData& world);

/// Parses and fully validates world file bytes; any fault is kCorrupt with a message naming
/// `nameForErrors` and the fault (never a crash, never an allocation beyond a small multiple
/// of bytes.size()). decodeWorld(encodeWorld(w)) == w exactly, stageSeconds aside (empty, or
/// the timings a file from before they were left out still holds).
base::Result<construction::WorldData> decodeWorld(std::string_view bytes,
                                                  std::string_view nameForErrors);

/// Writes `world` to `path` atomically: a temporary file in the same directory is written,
/// fsynced and renamed over `path`, then the directory is fsynced. On failure the target is
/// untouched, the temporary file removed, and the error is kIoError naming the path and cause
/// (if only the final directory fsync fails, the new file is in place but not yet durable).
/// First removes the stale temporaries of its directory (removeStaleWorldTemporaries), so a
/// killed earlier write leaves nothing behind for long.
base::Status writeWorldFile(const std::string& path, const construction::WorldData& world);

/// A temporary world file ("<name>.world.tmp.<pid>.<n>") older than this is stale even when
/// its PID names a live process (reused, or of another PID namespace sharing the directory):
/// a write takes seconds.
inline constexpr std::chrono::seconds kStaleTemporaryAge{3600};

/// Removes from `dir` the temporaries that writeWorldFile leaves when its process is killed
/// mid-write: those whose PID is no live process (other than this one) or older than
/// kStaleTemporaryAge. Returns how many were removed (none when `dir` cannot be read).
std::size_t removeStaleWorldTemporaries(const std::string& dir);

/// Reads a world file: kNotFound when it does not exist, kIoError when it cannot be read,
/// kCorrupt (see decodeWorld) when it is damaged, of another version, or over
/// kMaxWorldFileBytes.
base::Result<construction::WorldData> readWorldFile(const std::string& path);

} // namespace strahler::store
