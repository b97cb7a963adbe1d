#include "vegetation_params.h"

#include <cmath>
#include <iterator>

namespace strahler::input::detail {
namespace {

using base::ErrorCode;
using base::makeError;

/// The curves of a species in canonical (name) order, with where each lives.
struct Curve {
  const char* name;
  std::array<double, 4> SpeciesCurves::*member;
};
constexpr Curve kCurves[] = {{"humidity", &SpeciesCurves::humidity},
                             {"illumination", &SpeciesCurves::illumination},
                             {"sediment", &SpeciesCurves::sediment}};

constexpr double kLargest = 10000.0;

base::Error bad(const std::string& what) {
  return makeError(ErrorCode::kInvalidInput, "params: 'vegetation'" + what);
}

} // namespace

base::Status readVegetation(const Json& value, std::map<std::string, SpeciesCurves>& out) {
  if (!value.is_object())
    return bad(std::string(" must be an object of species (tree, bush), got ") +
               describeType(value));
  for (const auto& species : value.items()) {
    const std::string& name = species.key();
    bool known = false;
    for (const char* s : kVegetationSpecies)
      known = known || name == s;
    if (!known)
      return bad(": unknown species '" + printable(name) + "' (tree, bush)");
    if (!species.value().is_object())
      return bad("." + name +
                 " must be an object of the curves sediment, illumination and "
                 "humidity, got " +
                 describeType(species.value()));
    SpeciesCurves curves;
    std::size_t found = 0;
    for (const auto& curve : species.value().items()) {
      const Curve* c = nullptr;
      for (const Curve& k : kCurves)
        if (curve.key() == k.name)
          c = &k;
      if (!c)
        return bad("." + name + ": unknown curve '" + printable(curve.key()) +
                   "' (sediment, illumination, humidity)");
      const Json& numbers = curve.value();
      if (!numbers.is_array() || numbers.size() != 4)
        return bad("." + name + "." + c->name +
                   " must be an array of four numbers [rise0, rise1, fall1, fall0]");
      for (std::size_t k = 0; k < 4; ++k) {
        if (!numbers[k].is_number())
          return bad("." + name + "." + c->name + " must hold numbers, got " +
                     describeType(numbers[k]));
        (curves.*(c->member))[k] = numbers[k].get<double>();
      }
      ++found;
    }
    if (found != std::size(kCurves))
      return bad("." + name + " must set all three curves: sediment, illumination, humidity");
    out[name] = curves;
  }
  return base::Ok{};
}

base::Status checkVegetation(const std::map<std::string, SpeciesCurves>& vegetation) {
  for (const auto& [name, curves] : vegetation)
    for (const Curve& c : kCurves) {
      const std::array<double, 4>& v = curves.*(c.member);
      for (std::size_t k = 0; k < 4; ++k)
        if (!std::isfinite(v[k]) || v[k] < 0.0 || v[k] > kLargest || (k > 0 && v[k] < v[k - 1]))
          return makeError(ErrorCode::kOutOfRange,
                           "params: 'vegetation'." + name + "." + c.name +
                               " must be four non-decreasing numbers in [0, 10000], got [" +
                               formatNumber(v[0]) + ", " + formatNumber(v[1]) + ", " +
                               formatNumber(v[2]) + ", " + formatNumber(v[3]) + "]");
    }
  return base::Ok{};
}

std::string vegetationJson(const std::map<std::string, SpeciesCurves>& vegetation) {
  if (vegetation.empty())
    return "";
  std::string out = ",\"vegetation\":{";
  bool firstSpecies = true;
  for (const auto& [name, curves] : vegetation) {
    out += (firstSpecies ? "" : ",") + quoteJson(name) + ":{";
    firstSpecies = false;
    bool firstCurve = true;
    for (const Curve& c : kCurves) {
      const std::array<double, 4>& v = curves.*(c.member);
      out += std::string(firstCurve ? "" : ",") + "\"" + c.name + "\":[" + formatNumber(v[0]) +
             "," + formatNumber(v[1]) + "," + formatNumber(v[2]) + "," + formatNumber(v[3]) + "]";
      firstCurve = false;
    }
    out += "}";
  }
  return out + "}";
}

} // namespace strahler::input::detail
