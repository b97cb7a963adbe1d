#include "cli_args.h"

#include <charconv>

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
      return makeError(ErrorCode::kInvalidInput, "unknown option '" + name + "' for '" + command +
                                                     "' (see 'strahler " + command + " --help')");
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
