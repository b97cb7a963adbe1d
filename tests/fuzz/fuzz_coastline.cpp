// libFuzzer harness: a coastline GeoJSON through parseCoastline and, when it is valid, through
// makeWorldSpec (projection, area and extent limits), both with the default limits.
#include "fuzz_support.h"

#include "strahler/input/coastline.h"
#include "strahler/input/world_spec.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace strahler;
  const std::string_view text = fuzz::asText(data, size);
  const auto coast = input::parseCoastline(text);
  fuzz::requireNoInternalError(coast);
  if (!coast)
    return 0;
  fuzz::require(!coast.value().empty(), "a valid coastline has land");
  fuzz::requireNoInternalError(input::makeWorldSpec("fuzz", text, input::Params{}));
  return 0;
}
