#pragma once
// The same land written other ways: every ring reversed, every ring started elsewhere, the
// polygons in another order. For the tests that the world does not depend on the spelling.

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstddef>
#include <string>

namespace strahler::test_support {

/// How to rewrite a coastline's rings.
struct CoastlineRewrite {
  bool reverseRings = false;    ///< Every ring runs the other way.
  std::size_t rotateStart = 0;  ///< Every ring starts this many positions later (mod its size).
  bool reversePolygons = false; ///< A MultiPolygon's polygons (and holes) in reverse order.
};

namespace detail {

/// One ring of positions, closed (first == last), rewritten and closed again.
inline void rewriteRing(nlohmann::json& ring, const CoastlineRewrite& how) {
  if (!ring.is_array() || ring.size() < 4)
    return;
  ring.erase(ring.size() - 1); // the closing position
  if (how.reverseRings)
    std::reverse(ring.begin(), ring.end());
  const auto shift = static_cast<std::ptrdiff_t>(how.rotateStart % ring.size());
  std::rotate(ring.begin(), ring.begin() + shift, ring.end());
  ring.push_back(ring.front());
}

inline void rewritePolygon(nlohmann::json& rings, const CoastlineRewrite& how) {
  for (nlohmann::json& ring : rings)
    rewriteRing(ring, how);
  if (how.reversePolygons && rings.size() > 2)
    std::reverse(rings.begin() + 1, rings.end()); // the holes; the outer ring stays first
}

inline void rewriteGeometries(nlohmann::json& node, const CoastlineRewrite& how) {
  if (node.is_array()) {
    for (nlohmann::json& child : node)
      rewriteGeometries(child, how);
    if (how.reversePolygons && !node.empty() && node.front().is_object() &&
        node.front().value("type", "") == "Feature")
      std::reverse(node.begin(), node.end());
    return;
  }
  if (!node.is_object())
    return;
  const std::string type = node.value("type", "");
  if (type == "Polygon") {
    rewritePolygon(node["coordinates"], how);
  } else if (type == "MultiPolygon") {
    for (nlohmann::json& polygon : node["coordinates"])
      rewritePolygon(polygon, how);
    if (how.reversePolygons)
      std::reverse(node["coordinates"].begin(), node["coordinates"].end());
  } else {
    for (auto& [key, value] : node.items())
      rewriteGeometries(value, how);
  }
}

} // namespace detail

/// The GeoJSON coastline `geojson` rewritten as `how` says (numbers keep every bit: nlohmann
/// writes the shortest text that reads back as the same double).
inline std::string rewriteCoastline(const std::string& geojson, const CoastlineRewrite& how) {
  nlohmann::json root = nlohmann::json::parse(geojson);
  detail::rewriteGeometries(root, how);
  return root.dump();
}

} // namespace strahler::test_support
