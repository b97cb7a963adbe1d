#pragma once

#include "strahler/input/world_spec.h"

#include <vector>

namespace strahler::test_support {

/// The drawn features of issue 27 for Corsica (WGS84, as in tests/data/corsica-features.geojson):
/// five mountains, the main divide as one ridge, the Golo and the Tavignano (east of the
/// divide, mouths on the east coast), with local positions from `spec`'s projection. The
/// mouths are the (9.531, 42.547) and (9.556, 42.095) moved onto the coast of
/// tests/data/corsica.geojson (within 0.2 m of it), and the Golo's source moved from the
/// issue's (8.99, 42.28), which lies 2.4 km west of the ridge (the Golo crossed it), to
/// (9.04, 42.30), 2.9 km east of it.
inline input::Features corsicaDrawnFeatures(const input::WorldSpec& spec) {
  using geometry::Vec2;
  input::Features f;
  const auto local = [&](const std::vector<Vec2>& lonLat) {
    std::vector<Vec2> out;
    for (Vec2 p : lonLat)
      out.push_back(spec.projection.forward(p));
    return out;
  };
  const struct {
    Vec2 lonLat;
    double elevation;
  } mountains[] = {{{8.9456, 42.3797}, 2706.0},
                   {{9.0567, 42.2178}, 2622.0},
                   {{9.1003, 42.1556}, 2389.0},
                   {{9.1306, 42.0711}, 2352.0},
                   {{9.2028, 41.8553}, 2134.0}};
  for (const auto& m : mountains)
    f.mountains.push_back({m.lonLat, spec.projection.forward(m.lonLat), m.elevation, {}});
  const std::vector<Vec2> ridge{
      {8.83, 42.44}, {8.95, 42.38}, {9.06, 42.22}, {9.13, 42.07}, {9.20, 41.86}};
  f.ridges.push_back({ridge, local(ridge), {}});
  const std::vector<Vec2> golo{
      {9.04, 42.30}, {9.08, 42.40}, {9.25, 42.47}, {9.44, 42.53}, {9.53057, 42.54696}};
  const std::vector<Vec2> tavignano{
      {9.12, 42.27}, {9.16, 42.30}, {9.30, 42.20}, {9.45, 42.12}, {9.54503, 42.10320}};
  f.rivers.push_back({golo, local(golo), "Golo"});
  f.rivers.push_back({tavignano, local(tavignano), "Tavignano"});
  return f;
}

} // namespace strahler::test_support
