#include "strahler/construction/world_data.h"

namespace strahler::construction {

double WorldData::areaKm2() const noexcept {
  return geometry::area(land) / 1e6;
}

} // namespace strahler::construction
