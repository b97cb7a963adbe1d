#pragma once

#include "strahler/base/result.h"
#include "strahler/construction/world_data.h"
#include "strahler/input/world_spec.h"

#include <string>

namespace strahler::app {

/// Prints "strahler: error: <message>" to stderr; returns exit code 1: a file named on the
/// command line is wrong or unreadable, does not fit the options, or the work failed.
int fail(const base::Error& error);
/// Prints "strahler: error: <message>", then "see 'strahler <command> --help'", to stderr (never
/// the whole help); returns exit code 2: the command line itself is wrong (an unknown option, a
/// missing or malformed value, a value out of its range, options that do not go together),
/// which is known before any file is read. docs/cli.md, "Errors and exit codes".
int usageError(const base::Error& error, const std::string& command);
/// Prints the usage text to stdout; returns 0.
int printUsage(const char* usage);
/// Prints each change --repair made to the coastline of `spec` to stderr, one line each
/// ("strahler: repaired: self-intersection at (lon, lat), area km²: ..."), then each of its
/// warnings ("strahler: warning: ..."), even with --quiet: the user must see what was changed
/// and what looks wrong.
void printRepairsAndWarnings(const input::WorldSpec& spec);
/// Reads the world file `path` named on the command line. When it fails and the file is
/// GeoJSON (a coastline given where a world is expected), the error says so and what to do:
/// `hint`, e.g. "use --coast FILE".
base::Result<construction::WorldData> readWorldArgument(const std::string& path,
                                                        const std::string& hint);
/// The hint of readWorldArgument for commands that take only world files: generate one first.
std::string generateFirstHint(const std::string& path);
/// True when s ends with suffix.
bool endsWith(const std::string& s, const std::string& suffix);
/// Writes a text file atomically (temporary file, then rename).
base::Status writeTextFile(const std::string& path, const std::string& text);

} // namespace strahler::app
