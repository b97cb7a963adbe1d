#include "strahler/layers/vegetation_density.h"

#include "strahler/base/assert.h"
#include "strahler/input/params.h"

#include <algorithm>

namespace strahler::layers {

double ResponseCurve::operator()(double x) const noexcept {
  if (x < rise0 || x > fall0)
    return 0.0;
  if (x < rise1)
    return rise1 > rise0 ? (x - rise0) / (rise1 - rise0) : 1.0;
  if (x > fall1)
    return fall0 > fall1 ? (fall0 - x) / (fall0 - fall1) : 1.0;
  return 1.0;
}

Species speciesOf(const input::Params& params, std::size_t index) {
  STRAHLER_ASSERT(index < kSpecies.size(), "speciesOf: no such species");
  Species species = kSpecies[index];
  const auto set = params.vegetation.find(std::string(species.name));
  if (set == params.vegetation.end())
    return species;
  const auto curve = [](const std::array<double, 4>& v) {
    return ResponseCurve{v[0], v[1], v[2], v[3]};
  };
  species.sediment = curve(set->second.sediment);
  species.illumination = curve(set->second.illumination);
  species.humidity = curve(set->second.humidity);
  return species;
}

int speciesIndex(std::string_view name) noexcept {
  for (std::size_t i = 0; i < kSpecies.size(); ++i)
    if (kSpecies[i].name == name)
      return static_cast<int>(i);
  return -1;
}

double vegetationDensity(const Species& species, const Environment& e) noexcept {
  if (e.water)
    return 0.0;
  const double d = species.sediment(e.sedimentM) *
                   (species.illumination(e.illumination) + species.humidity(e.humidity));
  return std::clamp(0.5 * d, 0.0, 1.0);
}

std::vector<double> vegetationDensity(const Species& species, std::span<const double> sedimentM,
                                      std::span<const double> illumination,
                                      std::span<const double> humidity,
                                      std::span<const std::uint8_t> water) {
  const std::size_t n = sedimentM.size();
  STRAHLER_ASSERT(illumination.size() == n && humidity.size() == n && water.size() == n,
                  "vegetationDensity: the grids differ in size");
  std::vector<double> out(n);
  for (std::size_t i = 0; i < n; ++i)
    out[i] =
        vegetationDensity(species, {sedimentM[i], illumination[i], humidity[i], water[i] != 0});
  return out;
}

} // namespace strahler::layers
