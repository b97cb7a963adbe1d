#pragma once

// Private to core/store: POSIX file helpers with errors that name the path and errno text.

#include "strahler/base/result.h"

#include <cstdint>
#include <string>
#include <string_view>

namespace strahler::store::detail {

/// Replaces `path` by `bytes` atomically (temp file in the same directory, fsync, rename,
/// fsync of the directory). On failure: kIoError, temp file removed, target untouched unless
/// only the directory fsync failed (then the rename is done but not yet durable).
base::Status writeFileAtomically(const std::string& path, std::string_view bytes);

/// The whole content of `path`: kNotFound when missing, kIoError when unreadable or not a
/// regular file, kCorrupt when larger than `maxBytes` (checked before reading).
base::Result<std::string> readWholeFile(const std::string& path, std::uint64_t maxBytes);

} // namespace strahler::store::detail
