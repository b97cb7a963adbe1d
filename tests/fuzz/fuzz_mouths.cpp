// libFuzzer harness: user river mouths (GeoJSON Points with an optional "priority") through
// the input module's private reader, projected around Mallorca.
#include "fuzz_support.h"
#include "mouths.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace strahler;
  const geometry::LocalProjection projection(2.99, 39.6);
  const input::InputLimits limits;
  const auto mouths = input::detail::parseMouths(fuzz::asText(data, size), projection, limits);
  fuzz::requireNoInternalError(mouths);
  if (!mouths)
    return 0;
  fuzz::require(mouths.value().size() <= limits.maxMouths, "at most maxMouths mouths");
  for (const input::UserMouth& mouth : mouths.value())
    fuzz::require(mouth.priority >= 1, "priorities are at least 1");
  return 0;
}
