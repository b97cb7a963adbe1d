#pragma once

#include "strahler/base/result.h"

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace strahler::app {

/// Command-line options of one subcommand: `--name value`, `--name=value`, `-o value`, and
/// boolean flags `--name`.
class CliArgs {
public:
  /// Parses `args` (after the subcommand); `valued` lists options that take a value,
  /// `flags` those that do not. Unknown options and missing values are errors.
  static base::Result<CliArgs> parse(const std::string& command,
                                     const std::vector<std::string>& args,
                                     const std::set<std::string>& valued,
                                     const std::set<std::string>& flags);

  /// The value of option `name`, if given.
  std::optional<std::string> get(const std::string& name) const;
  /// True when flag `name` was given.
  bool has(const std::string& name) const { return flags_.count(name) > 0; }
  /// Option `name` as an integer in [lo, hi], or an error naming the option.
  base::Result<std::optional<long long>> getInt(const std::string& name, long long lo,
                                                long long hi) const;
  /// Option `name` as an unsigned 64-bit integer, or an error naming the option.
  base::Result<std::optional<std::uint64_t>> getU64(const std::string& name) const;
  /// Arguments that are not options, in order.
  const std::vector<std::string>& positional() const { return positional_; }

private:
  std::string command_;
  std::map<std::string, std::string> values_;
  std::set<std::string> flags_;
  std::vector<std::string> positional_;
};

/// The parts of a comma-separated option value, empty parts kept ("a,,b" → a, "", b).
std::vector<std::string> splitCommas(const std::string& text);

/// The name among `names` that `word` most likely misspells, for "did you mean": the nearest
/// by edit distance (adjacent transpositions count one) when it is at most 2, or a quarter of
/// the word's letters for longer words, and less than the letters (dashes not counted); else
/// one that `word` starts with or that starts with `word` (at least 3 letters in common:
/// "--coastline" → "--coast"). Empty when none is close.
std::string closestName(const std::string& word, const std::vector<std::string>& names);

} // namespace strahler::app
