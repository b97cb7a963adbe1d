#pragma once

// Private to core/store: POSIX file helpers with errors that name the path and errno text.

#include "strahler/base/result.h"

#include <chrono>
#include <cstdint>
#include <string>
#include <string_view>

namespace strahler::store::detail {

/// Replaces `path` by `bytes` atomically (temp file in the same directory, fsync, rename,
/// fsync of the directory). On failure: kIoError, temp file removed, target untouched unless
/// only the directory fsync failed (then the rename is done but not yet durable).
base::Status writeFileAtomically(const std::string& path, std::string_view bytes);

/// Removes the temporary files writeFileAtomically left in `dir` for targets named
/// `*<suffix>` ("<target>.tmp.<pid>.<n>") when their writer is gone: its PID is not a live
/// process (and not this one), or the file is older than `maxAge` (a write takes seconds; this
/// covers PIDs reused, or of another PID namespace sharing the directory). Returns how many
/// were removed; a missing or unreadable directory removes none.
std::size_t removeStaleTempFiles(const std::string& dir, std::string_view suffix,
                                 std::chrono::seconds maxAge);

/// The whole content of `path`: kNotFound when missing, kIoError when unreadable or not a
/// regular file, kCorrupt when larger than `maxBytes` (checked before reading).
base::Result<std::string> readWholeFile(const std::string& path, std::uint64_t maxBytes);

} // namespace strahler::store::detail
