// libFuzzer harness: params JSON through parseParams; a valid one must survive its documented
// round trip parseParams(canonicalJson(p)) == p.
#include "fuzz_support.h"

#include "strahler/input/params.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace strahler;
  const auto params = input::parseParams(fuzz::asText(data, size));
  fuzz::requireNoInternalError(params);
  if (!params)
    return 0;
  fuzz::require(input::validateParams(params.value()).ok(), "parsed params validate");
  const auto again = input::parseParams(input::canonicalJson(params.value()));
  fuzz::require(again.ok() && again.value() == params.value(), "canonicalJson round trip");
  return 0;
}
