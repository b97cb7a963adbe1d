#pragma once

#include "strahler/base/result.h"
#include "strahler/input/world_spec.h"

#include <string>

namespace strahler::app {

/// Prints "strahler: error: <message>" to stderr; returns exit code 1 (bad input, failure).
int fail(const base::Error& error);
/// Prints the message and the usage text to stderr; returns exit code 2 (bad command line).
int usageError(const base::Error& error, const char* usage);
/// Prints the usage text to stdout; returns 0.
int printUsage(const char* usage);
/// Prints each change --repair made to the coastline of `spec` to stderr, one line each
/// ("strahler: repaired: self-intersection at (lon, lat), area km²: ..."), then each of its
/// warnings ("strahler: warning: ..."), even with --quiet: the user must see what was changed
/// and what looks wrong.
void printRepairsAndWarnings(const input::WorldSpec& spec);
/// True when s ends with suffix.
bool endsWith(const std::string& s, const std::string& suffix);
/// Writes a text file atomically (temporary file, then rename).
base::Status writeTextFile(const std::string& path, const std::string& text);

} // namespace strahler::app
