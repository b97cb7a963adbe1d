#include "strahler/input/params.h"

#include "json_util.h"
#include "vegetation_params.h"

#include "strahler/base/guarded.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <exception>
#include <limits>
#include <new>
#include <variant>

namespace strahler::input {
namespace {

using base::ErrorCode;
using base::makeError;
using detail::formatNumber;
using detail::Json;

/// A numeric field: its JSON key and where it lives in Params.
struct Field {
  const char* name;
  std::variant<double Params::*, int Params::*> member;
};

// The JSON keys in canonical order; seed and constraints follow.
constexpr std::array<Field, 32> kFields{{
    {"edgeLength", &Params::edgeLength},
    {"sigma", &Params::sigma},
    {"delta", &Params::delta},
    {"kappa", &Params::kappa},
    {"zeta", &Params::zeta},
    {"probContinue", &Params::probContinue},
    {"probAsymmetric", &Params::probAsymmetric},
    {"probSymmetric", &Params::probSymmetric},
    {"branchAngle", &Params::branchAngle},
    {"angleJitter", &Params::angleJitter},
    {"fillBranches", &Params::fillBranches},
    {"slopeMin", &Params::slopeMin},
    {"slopeMax", &Params::slopeMax},
    {"slopeJitter", &Params::slopeJitter},
    {"coastRamp", &Params::coastRamp},
    {"maxPriority", &Params::maxPriority},
    {"mouthSpacing", &Params::mouthSpacing},
    {"accessibilityRadius", &Params::accessibilityRadius},
    {"lambda", &Params::lambda},
    {"lambdaCoastFactor", &Params::lambdaCoastFactor},
    {"concavity", &Params::concavity},
    {"referenceArea", &Params::referenceArea},
    {"straightMinSlope", &Params::straightMinSlope},
    {"braidedMinFlow", &Params::braidedMinFlow},
    {"braidedMaxDistance", &Params::braidedMaxDistance},
    {"deltaMinFlow", &Params::deltaMinFlow},
    {"tributaryLevels", &Params::tributaryLevels}, // canonical only when not 0
    {"erosionCell", &Params::erosionCell}, // the four erosion keys: only when erosionSteps > 0
    {"erosionSteps", &Params::erosionSteps},
    {"erosionStrength", &Params::erosionStrength},
    {"hillslopeDiffusivity", &Params::hillslopeDiffusivity},
    {"erosionGrain", &Params::erosionGrain},
}};

std::string quoted(std::string_view key) {
  return "'" + detail::printable(key) + "'";
}

/// Case-insensitive Levenshtein distance (keys are short: O(|a| |b|) is fine).
std::size_t editDistance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j)
    row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                        std::tolower(static_cast<unsigned char>(b[j - 1]));
      const std::size_t next = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (same ? 0 : 1)});
      diagonal = row[j];
      row[j] = next;
    }
  }
  return row[b.size()];
}

/// "unknown key 'sigmaa' (did you mean 'sigma'?)" when a known key is ≤ 2 edits away.
base::Error unknownKey(const std::string& where, std::string_view key,
                       const std::vector<std::string_view>& known) {
  std::string message = where + "unknown key " + quoted(key);
  std::size_t best = 3;
  std::string_view suggestion;
  if (key.size() <= 64)
    for (std::string_view candidate : known) {
      const std::size_t d = editDistance(key, candidate);
      if (d < best) {
        best = d;
        suggestion = candidate;
      }
    }
  if (!suggestion.empty())
    message += " (did you mean " + quoted(suggestion) + "?)";
  return makeError(ErrorCode::kInvalidInput, message);
}

base::Error wrongType(std::string_view key, const char* expected, const Json& value) {
  return makeError(ErrorCode::kInvalidInput, "params: " + quoted(key) + " must be " + expected +
                                                 ", got " + detail::describeType(value));
}

base::Status readDouble(std::string_view key, const Json& value, double& out) {
  if (!value.is_number())
    return wrongType(key, "a number", value);
  out = value.get<double>();
  return base::Ok{};
}

base::Status readInt(std::string_view key, const Json& value, int& out) {
  if (!value.is_number())
    return wrongType(key, "an integer", value);
  const double v = value.get<double>();
  if (v != std::floor(v))
    return makeError(ErrorCode::kInvalidInput,
                     "params: " + quoted(key) + " must be an integer, got " + formatNumber(v));
  if (!(v >= std::numeric_limits<int>::min() && v <= std::numeric_limits<int>::max()))
    return makeError(ErrorCode::kOutOfRange,
                     "params: " + quoted(key) + " = " + formatNumber(v) + " is out of range");
  out = static_cast<int>(v);
  return base::Ok{};
}

base::Status readSeed(const Json& value, std::uint64_t& out) {
  if (value.is_number_unsigned()) {
    out = value.get<std::uint64_t>();
    return base::Ok{};
  }
  if (value.is_number_integer() && value.get<std::int64_t>() >= 0) { // "-0"
    out = 0;
    return base::Ok{};
  }
  if (value.is_number_integer())
    return makeError(ErrorCode::kOutOfRange, "params: 'seed' must be a non-negative integer, got " +
                                                 std::to_string(value.get<std::int64_t>()));
  if (value.is_number_float()) {
    const double v = value.get<double>();
    if (v != std::floor(v) || v < 0.0)
      return makeError(ErrorCode::kInvalidInput,
                       "params: 'seed' must be a non-negative integer, got " + formatNumber(v));
    if (v >= 18446744073709551616.0)
      return makeError(ErrorCode::kOutOfRange, "params: 'seed' = " + formatNumber(v) +
                                                   " is larger than 2^64-1 = "
                                                   "18446744073709551615");
    if (v > 9007199254740992.0) // 2^53: above it a JSON number may not be exact
      return makeError(ErrorCode::kInvalidInput,
                       "params: 'seed' = " + formatNumber(v) +
                           " is above 2^53 and not exact as a JSON number; write it as a "
                           "decimal string, e.g. \"18446744073709551615\"");
    out = static_cast<std::uint64_t>(v);
    return base::Ok{};
  }
  if (!value.is_string())
    return wrongType("seed", "a non-negative integer or a decimal string", value);
  const std::string& text = value.get_ref<const std::string&>();
  const bool digits =
      !text.empty() && text.size() <= 64 &&
      std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
  if (!digits)
    return makeError(ErrorCode::kInvalidInput,
                     "params: 'seed' string must hold only decimal digits, got " +
                         detail::quoteJson(text.substr(0, 40)));
  const auto result = std::from_chars(text.data(), text.data() + text.size(), out);
  if (result.ec != std::errc() || result.ptr != text.data() + text.size())
    return makeError(ErrorCode::kOutOfRange,
                     "params: 'seed' = " + text + " is larger than 2^64-1 = 18446744073709551615");
  return base::Ok{};
}

base::Result<ConstraintSource> readConstraint(const Json& value, std::size_t index) {
  const std::string where = "params: constraints[" + std::to_string(index) + "]: ";
  if (!value.is_object())
    return makeError(ErrorCode::kInvalidInput,
                     where + "must be an object {\"kind\", \"image\", \"bounds\"}, got " +
                         detail::describeType(value));
  static const std::vector<std::string_view> kKeys{"kind", "image", "bounds"};
  for (const auto& [key, member] : value.items())
    if (std::find(kKeys.begin(), kKeys.end(), key) == kKeys.end())
      return unknownKey(where, key, kKeys);
  for (std::string_view key : kKeys)
    if (!value.contains(key))
      return makeError(ErrorCode::kInvalidInput, where + "missing " + quoted(key));
  ConstraintSource source;
  const Json& kind = value["kind"];
  if (kind == "mountainousness")
    source.kind = ConstraintKind::kMountainousness;
  else if (kind == "riverSlope")
    source.kind = ConstraintKind::kRiverSlope;
  else
    return makeError(ErrorCode::kInvalidInput,
                     where + "'kind' is " +
                         (kind.is_string()
                              ? "\"" + detail::printable(kind.get_ref<const std::string&>()) + "\""
                              : std::string(detail::describeType(kind))) +
                         "; expected \"mountainousness\" or \"riverSlope\"");
  const Json& image = value["image"];
  if (!image.is_string())
    return makeError(ErrorCode::kInvalidInput, where + "'image' must be a string (a path), got " +
                                                   detail::describeType(image));
  source.imagePath = image.get<std::string>();
  const Json& bounds = value["bounds"];
  if (!bounds.is_array() || bounds.size() != 4 ||
      !std::all_of(bounds.begin(), bounds.end(), [](const Json& b) { return b.is_number(); }))
    return makeError(ErrorCode::kInvalidInput,
                     where + "'bounds' must be an array of 4 numbers [west, south, east, north]");
  source.bounds = {bounds[0].get<double>(), bounds[1].get<double>(), bounds[2].get<double>(),
                   bounds[3].get<double>()};
  return source;
}

base::Status readConstraints(const Json& value, std::vector<ConstraintSource>& out) {
  if (!value.is_array())
    return wrongType("constraints", "an array of {\"kind\", \"image\", \"bounds\"} objects", value);
  if (value.size() > kMaxConstraints)
    return makeError(ErrorCode::kLimitExceeded,
                     "params: 'constraints' has " + std::to_string(value.size()) +
                         " entries, the limit is " + std::to_string(kMaxConstraints));
  out.clear();
  for (std::size_t i = 0; i < value.size(); ++i) {
    STRAHLER_ASSIGN_OR_RETURN(ConstraintSource source, readConstraint(value[i], i));
    out.push_back(std::move(source));
  }
  return base::Ok{};
}

base::Result<Params> parseParamsUnguarded(std::string_view json, const InputLimits& limits) {
  detail::JsonLimits jsonLimits;
  jsonLimits.maxBytes = limits.maxFileBytes;
  jsonLimits.maxDepth = limits.maxJsonDepth;
  jsonLimits.maxValues = 4096; // 26 keys and 16 constraints need far fewer
  STRAHLER_ASSIGN_OR_RETURN(const Json root, detail::parseJson(json, "params", jsonLimits));
  if (!root.is_object())
    return makeError(ErrorCode::kInvalidInput, std::string("params: expected a JSON object, got ") +
                                                   detail::describeType(root));
  std::vector<std::string_view> known;
  for (const Field& f : kFields)
    known.push_back(f.name);
  known.push_back("seed");
  known.push_back("constraints");
  known.push_back("vegetation");
  known.push_back("grower");

  Params params;
  for (const auto& item : root.items()) {
    // Named, not a structured binding: clang 14 (the fuzz preset) cannot capture bindings.
    const std::string& key = item.key();
    const Json& value = item.value();
    const auto field =
        std::find_if(kFields.begin(), kFields.end(), [&](const Field& f) { return key == f.name; });
    if (field != kFields.end()) {
      if (auto* d = std::get_if<double Params::*>(&field->member))
        STRAHLER_RETURN_IF_ERROR(readDouble(key, value, params.*(*d)));
      else
        STRAHLER_RETURN_IF_ERROR(
            readInt(key, value, params.*std::get<int Params::*>(field->member)));
    } else if (key == "seed") {
      STRAHLER_RETURN_IF_ERROR(readSeed(value, params.seed));
    } else if (key == "constraints") {
      STRAHLER_RETURN_IF_ERROR(readConstraints(value, params.constraints));
    } else if (key == "vegetation") {
      STRAHLER_RETURN_IF_ERROR(detail::readVegetation(value, params.vegetation));
    } else if (key == "grower") {
      if (!value.is_string())
        return wrongType(key, "a string (\"grammar\" or \"dla\")", value);
      STRAHLER_ASSIGN_OR_RETURN(params.grower, parseGrower(value.get_ref<const std::string&>()),
                                "params: 'grower'");
    } else {
      return unknownKey("params: ", key, known);
    }
  }
  STRAHLER_RETURN_IF_ERROR(validateParams(params));
  return params;
}

/// One range rule: lo/hi with open or closed ends; an infinite hi means "no upper bound".
struct Range {
  const char* name;
  double value;
  double lo;
  double hi;
  bool loClosed;
  bool hiClosed;
  const char* unit;
};

base::Status checkRange(const Range& r) {
  const std::string unit = r.unit[0] != '\0' ? std::string(" ") + r.unit : std::string();
  if (!std::isfinite(r.value))
    return makeError(ErrorCode::kOutOfRange,
                     "params: " + quoted(r.name) + " is not a finite number");
  const bool aboveLo = r.loClosed ? r.value >= r.lo : r.value > r.lo;
  const bool belowHi = r.hiClosed ? r.value <= r.hi : r.value < r.hi;
  if (aboveLo && belowHi)
    return base::Ok{};
  std::string rule;
  if (std::isinf(r.hi))
    rule = std::string("must be ") + (r.loClosed ? ">= " : "> ") + formatNumber(r.lo) + unit;
  else
    rule = std::string("is outside ") + (r.loClosed ? "[" : "(") + formatNumber(r.lo) + ", " +
           formatNumber(r.hi) + (r.hiClosed ? "]" : ")") + unit;
  return makeError(ErrorCode::kOutOfRange,
                   "params: " + quoted(r.name) + " = " + formatNumber(r.value) + unit + " " + rule);
}

std::string fixed(double v) {
  std::array<char, 32> buffer{};
  std::snprintf(buffer.data(), buffer.size(), "%.6g", v);
  return buffer.data();
}

base::Status checkConstraint(const ConstraintSource& c, std::size_t i) {
  const std::string where = "params: constraints[" + std::to_string(i) + "]: ";
  if (c.kind != ConstraintKind::kMountainousness && c.kind != ConstraintKind::kRiverSlope)
    return makeError(ErrorCode::kInvalidInput, where + "unknown constraint kind");
  if (c.imagePath.empty())
    return makeError(ErrorCode::kInvalidInput, where + "'image' is an empty path");
  const GeoBounds& b = c.bounds;
  const std::string text = "[" + formatNumber(b.west) + ", " + formatNumber(b.south) + ", " +
                           formatNumber(b.east) + ", " + formatNumber(b.north) + "]";
  for (double lon : {b.west, b.east})
    if (!(lon >= -180.0 && lon <= 180.0))
      return makeError(ErrorCode::kOutOfRange,
                       where + "bounds " + text + ": longitude outside [-180, 180]");
  for (double lat : {b.south, b.north})
    if (!(lat >= -90.0 && lat <= 90.0))
      return makeError(ErrorCode::kOutOfRange,
                       where + "bounds " + text + ": latitude outside [-90, 90]");
  if (!(b.west < b.east) || !(b.south < b.north))
    return makeError(ErrorCode::kInvalidInput,
                     where + "bounds " + text +
                         " must be [west, south, east, north] with west < east and south < north");
  return base::Ok{};
}

} // namespace

const char* growerName(NetworkGrower grower) noexcept {
  return grower == NetworkGrower::kDla ? "dla" : "grammar";
}

base::Result<NetworkGrower> parseGrower(std::string_view name) {
  if (name == "grammar")
    return NetworkGrower::kGrammar;
  if (name == "dla")
    return NetworkGrower::kDla;
  return makeError(ErrorCode::kInvalidInput, "unknown grower " + quoted(name) +
                                                 ": expected \"grammar\" (the paper's open "
                                                 "grammar) or \"dla\" (diffusion-limited "
                                                 "aggregation)");
}

base::Status validateParams(const Params& p) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const Range ranges[] = {
      {"edgeLength", p.edgeLength, 50.0, 20000.0, true, true, "m"},
      {"sigma", p.sigma, 0.0, kInf, false, false, "m"},
      {"delta", p.delta, 0.0, kInf, true, false, "m"},
      {"kappa", p.kappa, 0.0, 10.0, false, true, ""},
      {"zeta", p.zeta, 0.0, kInf, true, false, "m"},
      {"probContinue", p.probContinue, 0.0, 1.0, true, true, ""},
      {"probAsymmetric", p.probAsymmetric, 0.0, 1.0, true, true, ""},
      {"probSymmetric", p.probSymmetric, 0.0, 1.0, true, true, ""},
      {"branchAngle", p.branchAngle, 0.0, 90.0, false, true, "degrees"},
      {"angleJitter", p.angleJitter, 0.0, 60.0, true, true, "degrees"},
      {"fillBranches", double(p.fillBranches), 1.0, 2.0, true, true, ""},
      {"slopeMin", p.slopeMin, 0.0, kInf, true, false, ""},
      {"slopeMax", p.slopeMax, 0.0, kInf, true, false, ""},
      {"slopeJitter", p.slopeJitter, 0.0, 1.0, true, false, ""},
      {"coastRamp", p.coastRamp, 0.0, kInf, false, false, "m"},
      {"maxPriority", double(p.maxPriority), 1.0, 12.0, true, true, ""},
      {"mouthSpacing", p.mouthSpacing, 0.0, kInf, false, false, "m"},
      {"accessibilityRadius", p.accessibilityRadius, 0.0, kInf, false, false, "m"},
      {"lambda", p.lambda, 0.0, 1.0, true, true, ""},
      {"lambdaCoastFactor", p.lambdaCoastFactor, 0.0, 1.0, false, true, ""},
      {"concavity", p.concavity, 0.0, 1.0, true, true, ""},
      {"referenceArea", p.referenceArea, 0.0, 10000.0, false, true, "km²"},
      {"straightMinSlope", p.straightMinSlope, 0.0, kInf, true, false, ""},
      {"braidedMinFlow", p.braidedMinFlow, 0.0, kInf, true, false, "m³/s"},
      {"braidedMaxDistance", p.braidedMaxDistance, 0.0, kInf, true, false, "m"},
      {"deltaMinFlow", p.deltaMinFlow, 0.0, kInf, true, false, "m³/s"},
      {"tributaryLevels", double(p.tributaryLevels), 0.0, 3.0, true, true, ""},
      {"erosionCell", p.erosionCell, 30.0, 120.0, true, true, "m"},
      {"erosionSteps", double(p.erosionSteps), 0.0, 200.0, true, true, ""},
      {"erosionStrength", p.erosionStrength, 0.0, 5.0, true, true, ""},
      {"hillslopeDiffusivity", p.hillslopeDiffusivity, 0.0, 5.0, true, true, ""},
      {"erosionGrain", p.erosionGrain, 0.0, 5.0, true, true, ""},
  };
  for (const Range& r : ranges)
    STRAHLER_RETURN_IF_ERROR(checkRange(r));

  const double minSigma = p.edgeLength / std::sqrt(2.0);
  if (!(p.sigma > minSigma))
    return makeError(ErrorCode::kInvalidInput,
                     "params: 'sigma' σ = " + formatNumber(p.sigma) +
                         " m must be greater than e/√2 = " + fixed(minSigma) +
                         " m (edgeLength e = " + formatNumber(p.edgeLength) +
                         " m), or non-adjacent edges could not keep σ apart");
  if (!(p.delta < 10.0 * p.edgeLength))
    return makeError(ErrorCode::kInvalidInput, "params: 'delta' = " + formatNumber(p.delta) +
                                                   " m must be less than 10 edgeLength = " +
                                                   formatNumber(10.0 * p.edgeLength) + " m");
  const double sum = p.probContinue + p.probAsymmetric + p.probSymmetric;
  if (!(std::abs(sum - 1.0) <= 1e-6))
    return makeError(ErrorCode::kInvalidInput,
                     "params: probContinue + probAsymmetric + probSymmetric = " + fixed(sum) +
                         " (" + formatNumber(p.probContinue) + " + " +
                         formatNumber(p.probAsymmetric) + " + " + formatNumber(p.probSymmetric) +
                         ") must equal 1 (within 1e-6)");
  if (!(p.slopeMin <= p.slopeMax))
    return makeError(ErrorCode::kInvalidInput,
                     "params: 'slopeMin' = " + formatNumber(p.slopeMin) +
                         " must not exceed 'slopeMax' = " + formatNumber(p.slopeMax));
  if (!(p.slopeMax < p.kappa))
    return makeError(ErrorCode::kInvalidInput,
                     "params: 'slopeMax' = " + formatNumber(p.slopeMax) +
                         " must be less than 'kappa' κ = " + formatNumber(p.kappa) +
                         " (rivers could not climb at that slope)");
  if (p.grower != NetworkGrower::kGrammar && p.grower != NetworkGrower::kDla)
    return makeError(ErrorCode::kInvalidInput, "params: 'grower' is not a known grower");
  if (p.constraints.size() > kMaxConstraints)
    return makeError(ErrorCode::kLimitExceeded,
                     "params: 'constraints' has " + std::to_string(p.constraints.size()) +
                         " entries, the limit is " + std::to_string(kMaxConstraints));
  for (std::size_t i = 0; i < p.constraints.size(); ++i)
    STRAHLER_RETURN_IF_ERROR(checkConstraint(p.constraints[i], i));
  return detail::checkVegetation(p.vegetation);
}

base::Result<Params> parseParams(std::string_view json, const InputLimits& limits) {
  return base::guarded("params", [&] { return parseParamsUnguarded(json, limits); });
}

std::string canonicalJson(const Params& params) {
  std::string out = "{";
  for (const Field& f : kFields) {
    if (std::string_view(f.name) == "tributaryLevels" && params.tributaryLevels == 0)
      continue; // worlds from before it keep their canonical text
    if (params.erosionSteps == 0 && std::string_view(f.name).starts_with("erosion"))
      continue; // likewise for worlds without erosion
    if (params.erosionSteps == 0 && std::string_view(f.name) == "hillslopeDiffusivity")
      continue;
    out += "\"" + std::string(f.name) + "\":";
    if (auto* d = std::get_if<double Params::*>(&f.member))
      out += formatNumber(params.*(*d));
    else
      out += std::to_string(params.*std::get<int Params::*>(f.member));
    out += ",";
  }
  out += "\"seed\":" + std::to_string(params.seed) + ",\"constraints\":[";
  for (std::size_t i = 0; i < params.constraints.size(); ++i) {
    const ConstraintSource& c = params.constraints[i];
    if (i > 0)
      out += ",";
    out += std::string("{\"kind\":") +
           (c.kind == ConstraintKind::kRiverSlope ? "\"riverSlope\"" : "\"mountainousness\"") +
           ",\"image\":" + detail::quoteJson(c.imagePath) + ",\"bounds\":[" +
           formatNumber(c.bounds.west) + "," + formatNumber(c.bounds.south) + "," +
           formatNumber(c.bounds.east) + "," + formatNumber(c.bounds.north) + "]}";
  }
  out += "]" + detail::vegetationJson(params.vegetation);
  if (params.grower != NetworkGrower::kGrammar) // worlds from before it keep their text
    out += std::string(",\"grower\":\"") + growerName(params.grower) + "\"";
  return out + "}";
}

} // namespace strahler::input
