#include "world_limits.h"

namespace strahler::app {

base::Result<input::InputLimits> worldLimits(const CliArgs& args) {
  input::InputLimits limits;
  auto area = args.getInt(kMaxAreaOption, 1, 100'000'000);
  if (!area)
    return area.error();
  auto extent = args.getInt(kMaxExtentOption, 1, 40'000);
  if (!extent)
    return extent.error();
  if (area.value())
    limits.maxAreaKm2 = static_cast<double>(*area.value());
  if (extent.value())
    limits.maxExtentKm = static_cast<double>(*extent.value());
  return limits;
}

} // namespace strahler::app
