#pragma once
// params.json's "vegetation" object (Params::vegetation): reading, checking and its canonical
// JSON, apart from the generation's numeric fields in params.cpp.

#include "json_util.h"

#include "strahler/input/params.h"

#include <map>
#include <string>

namespace strahler::input::detail {

/// Reads "vegetation": an object of species (kVegetationSpecies) to objects of exactly the
/// three curves, each an array of four numbers. kInvalidInput naming the key for anything else;
/// the values are checked by checkVegetation().
base::Status readVegetation(const Json& value, std::map<std::string, SpeciesCurves>& out);

/// kOutOfRange naming the curve unless every curve is finite, non-decreasing, in [0, 10000].
base::Status checkVegetation(const std::map<std::string, SpeciesCurves>& vegetation);

/// ',"vegetation":{...}' in canonical form (species and curves in name order), or "" when
/// empty.
std::string vegetationJson(const std::map<std::string, SpeciesCurves>& vegetation);

} // namespace strahler::input::detail
