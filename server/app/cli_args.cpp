#include "cli_args.h"

#include <algorithm>
#include <charconv>
#include <string_view>

namespace strahler::app {

using base::ErrorCode;
using base::makeError;

base::Result<CliArgs> CliArgs::parse(const std::string& command,
                                     const std::vector<std::string>& args,
                                     const std::set<std::string>& valued,
                                     const std::set<std::string>& flags) {
  CliArgs out;
  out.command_ = command;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (arg.size() < 2 || arg[0] != '-') {
      out.positional_.push_back(arg);
      continue;
    }
    std::string name = arg;
    std::optional<std::string> inlineValue;
    if (const auto eq = arg.find('='); eq != std::string::npos) {
      name = arg.substr(0, eq);
      inlineValue = arg.substr(eq + 1);
    }
    if (flags.count(name)) {
      if (inlineValue)
        return makeError(ErrorCode::kInvalidInput, "option '" + name + "' takes no value");
      out.flags_.insert(name);
    } else if (valued.count(name)) {
      if (!inlineValue && i + 1 >= args.size())
        return makeError(ErrorCode::kInvalidInput, "option '" + name + "' needs a value");
      out.values_[name] = inlineValue ? *inlineValue : args[++i];
    } else {
      std::vector<std::string> known(valued.begin(), valued.end());
      known.insert(known.end(), flags.begin(), flags.end());
      const std::string guess = closestName(name, known);
      return makeError(ErrorCode::kInvalidInput,
                       "unknown option '" + name + "' for '" + command + "'" +
                           (guess.empty() ? "" : "; did you mean '" + guess + "'?"));
    }
  }
  return out;
}

std::optional<std::string> CliArgs::get(const std::string& name) const {
  const auto it = values_.find(name);
  if (it == values_.end())
    return std::nullopt;
  return it->second;
}

base::Result<std::optional<long long>> CliArgs::getInt(const std::string& name, long long lo,
                                                       long long hi) const {
  const auto text = get(name);
  if (!text)
    return std::optional<long long>();
  long long v = 0;
  const auto [end, ec] = std::from_chars(text->data(), text->data() + text->size(), v);
  if (ec != std::errc() || end != text->data() + text->size() || v < lo || v > hi)
    return makeError(ErrorCode::kInvalidInput, "option '" + name + "' must be an integer in [" +
                                                   std::to_string(lo) + ", " + std::to_string(hi) +
                                                   "], got '" + *text + "'");
  return std::optional<long long>(v);
}

base::Result<std::optional<std::uint64_t>> CliArgs::getU64(const std::string& name) const {
  const auto text = get(name);
  if (!text)
    return std::optional<std::uint64_t>();
  std::uint64_t v = 0;
  const auto [end, ec] = std::from_chars(text->data(), text->data() + text->size(), v);
  if (ec != std::errc() || end != text->data() + text->size())
    return makeError(ErrorCode::kInvalidInput, "option '" + name +
                                                   "' must be an integer in [0, 2^64 - 1], got '" +
                                                   *text + "'");
  return std::optional<std::uint64_t>(v);
}

namespace {

/// Edit distance with adjacent transpositions (optimal string alignment): "sevre" is one edit
/// from "serve". Names are short: O(|a| |b|) is fine.
std::size_t editDistance(std::string_view a, std::string_view b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i)
    d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j)
    d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i)
    for (std::size_t j = 1; j <= b.size(); ++j) {
      d[i][j] = std::min(
          {d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

std::string_view withoutDashes(std::string_view name) {
  return name.substr(std::min(name.find_first_not_of('-'), name.size()));
}

} // namespace

std::string closestName(const std::string& word, const std::vector<std::string>& names) {
  const std::string_view letters = withoutDashes(word);
  if (letters.empty() || word.size() > 64)
    return "";
  // Two edits for names of up to 8 letters ("sever" → "serve"), a quarter of longer ones; never
  // as many as the word has letters.
  const std::size_t allowed =
      std::min(letters.size() - 1, std::max<std::size_t>(2, letters.size() / 4));
  std::string best;
  std::size_t bestDistance = allowed + 1;
  for (const std::string& name : names) {
    const std::size_t d = editDistance(word, name);
    if (d < bestDistance) {
      bestDistance = d;
      best = name;
    }
  }
  if (!best.empty())
    return best;
  std::size_t bestCommon = 2;
  for (const std::string& name : names) {
    const std::string_view other = withoutDashes(name);
    const std::size_t common = std::min(letters.size(), other.size());
    if (common > bestCommon && letters.substr(0, common) == other.substr(0, common)) {
      bestCommon = common;
      best = name;
    }
  }
  return best;
}

std::vector<std::string> splitCommas(const std::string& text) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = text.find(',', start);
    parts.push_back(text.substr(start, comma - start));
    if (comma == std::string::npos)
      return parts;
    start = comma + 1;
  }
}

} // namespace strahler::app
