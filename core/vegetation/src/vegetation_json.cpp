#include "strahler/vegetation/vegetation_json.h"

#include "strahler/base/assert.h"

#include <charconv>
#include <cstdio>

namespace strahler::vegetation {
namespace {

/// Appends `value` with `digits` fixed decimals (std::to_chars: no locale, shortest sign).
void appendFixed(std::string& out, double value, int digits) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, value, std::chars_format::fixed, digits);
  out.append(buf, r.ptr);
}

void appendInteger(std::string& out, std::int64_t value) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, value);
  out.append(buf, r.ptr);
}

} // namespace

std::string writeVegetationJson(const geometry::TileId& tile,
                                const geometry::LocalProjection& projection,
                                std::span<const Instance> instances,
                                std::span<const double> heights) {
  STRAHLER_ASSERT(heights.empty() || heights.size() == instances.size(),
                  "vegetation JSON: one height per instance");
  std::string out;
  out.reserve(256 + instances.size() * (heights.empty() ? 150 : 190));
  out += "{\"tile\":[";
  appendInteger(out, tile.z);
  out += ',';
  appendInteger(out, tile.x);
  out += ',';
  appendInteger(out, tile.y);
  out += "],\"species\":[";
  for (std::size_t s = 0; s < kSpecies.size(); ++s) {
    out += s ? ",{\"name\":\"" : "{\"name\":\"";
    out += kSpecies[s].name;
    out += "\",\"spacing\":";
    appendFixed(out, kSpecies[s].spacing, 2);
    out += ",\"max_radius\":";
    appendFixed(out, kSpecies[s].maxRadius, 2);
    out += '}';
  }
  out += "],\"instances\":[";
  for (std::size_t i = 0; i < instances.size(); ++i) {
    const Instance& inst = instances[i];
    const geometry::Vec2 lonLat = projection.inverse(inst.position);
    const geometry::Vec2 t = tileCoordinates(tile, lonLat);
    out += i ? ",{\"species\":" : "{\"species\":";
    appendInteger(out, inst.species);
    out += ",\"x\":";
    appendFixed(out, t.x, 7);
    out += ",\"y\":";
    appendFixed(out, t.y, 7);
    out += ",\"lon\":";
    appendFixed(out, lonLat.x, 7);
    out += ",\"lat\":";
    appendFixed(out, lonLat.y, 7);
    out += ",\"radius\":";
    appendFixed(out, inst.radius, 2);
    out += ",\"rotation\":";
    appendFixed(out, inst.rotation, 3);
    out += ",\"scale\":";
    appendFixed(out, inst.scale, 3);
    if (!heights.empty()) {
      out += ",\"e\":";
      appendFixed(out, inst.position.x, 2);
      out += ",\"n\":";
      appendFixed(out, inst.position.y, 2);
      out += ",\"h\":";
      appendFixed(out, heights[i], 2);
    }
    char id[17];
    std::snprintf(id, sizeof id, "%016llx", static_cast<unsigned long long>(inst.id));
    out += ",\"id\":\"";
    out += id;
    out += "\"}";
  }
  out += "]}";
  return out;
}

} // namespace strahler::vegetation
