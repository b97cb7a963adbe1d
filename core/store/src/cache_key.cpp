#include "strahler/store/cache_key.h"

#include <charconv>
#include <cstdint>
#include <cstring>
#include <optional>
#include <vector>

namespace strahler::store {
namespace {

std::uint64_t splitmix64(std::uint64_t z) noexcept {
  z += 0x9E3779B97F4A7C15ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

/// Two independent 64-bit hashes of one byte stream: FNV-1a, and splitmix64 chained over
/// little-endian 8-byte words. Defined on bytes only, so it is the same on every machine.
class Hash128 {
public:
  void add(std::string_view bytes) noexcept {
    for (const char c : bytes)
      addByte(static_cast<std::uint8_t>(c));
  }
  void addU32(std::uint32_t v) noexcept {
    for (int i = 0; i < 4; ++i)
      addByte(static_cast<std::uint8_t>(v >> (8 * i)));
  }
  /// 32 lower-case hex digits.
  std::string hex() const {
    const std::uint64_t mixed = splitmix64(splitmix64(mix_ ^ word_) ^ length_);
    return hex64(fnv_) + hex64(mixed);
  }

private:
  void addByte(std::uint8_t b) noexcept {
    fnv_ = (fnv_ ^ b) * 0x100000001B3ull;
    word_ |= std::uint64_t{b} << (8 * filled_);
    if (++filled_ == 8) {
      mix_ = splitmix64(mix_ ^ word_);
      word_ = 0;
      filled_ = 0;
    }
    ++length_;
  }
  static std::string hex64(std::uint64_t v) {
    static constexpr char kDigits[] = "0123456789abcdef";
    std::string out(16, '0');
    for (int i = 15; i >= 0; --i, v >>= 4)
      out[static_cast<std::size_t>(i)] = kDigits[v & 0xFu];
    return out;
  }

  std::uint64_t fnv_ = 0xCBF29CE484222325ull;
  std::uint64_t mix_ = 0x6A09E667F3BCC909ull;
  std::uint64_t word_ = 0;
  std::uint64_t length_ = 0;
  int filled_ = 0;
};

/// Shortest decimal that reads back as exactly `v`.
void appendNumber(std::string& out, double v) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, v);
  out.append(buffer, result.ptr);
}

/// "<length>:<text>", so that no text can be mistaken for the fields after it.
void appendText(std::string& out, std::string_view label, std::string_view text) {
  out.append(label).append(" ").append(std::to_string(text.size())).append(":");
  out.append(text).append("\n");
}

void appendLand(std::string& out, const geometry::MultiPolygon& land) {
  out.append("land ").append(std::to_string(land.size())).append("\n");
  const auto appendRing = [&out](const geometry::Ring& ring) {
    out.append("ring ").append(std::to_string(ring.size())).append("\n");
    for (const geometry::Vec2 p : ring) {
      appendNumber(out, p.x);
      out.push_back(' ');
      appendNumber(out, p.y);
      out.push_back('\n');
    }
  };
  for (const geometry::Polygon& polygon : land) {
    out.append("polygon ").append(std::to_string(1 + polygon.holes.size())).append("\n");
    appendRing(polygon.outer);
    for (const geometry::Ring& hole : polygon.holes)
      appendRing(hole);
  }
}

void appendMouths(std::string& out, const std::vector<input::UserMouth>& mouths) {
  out.append("mouths ").append(std::to_string(mouths.size())).append("\n");
  for (const input::UserMouth& mouth : mouths) {
    appendNumber(out, mouth.lonLat.x);
    out.push_back(' ');
    appendNumber(out, mouth.lonLat.y);
    out.append(" ").append(std::to_string(mouth.priority)).append("\n");
  }
}

std::string pixelHash(const image::GrayImage& image) {
  Hash128 hash;
  for (const float v : image.pixels) {
    std::uint32_t bits = 0;
    std::memcpy(&bits, &v, sizeof bits);
    hash.addU32(bits);
  }
  return hash.hex();
}

void appendConstraints(std::string& out, const std::vector<input::ConstraintMap>& maps) {
  out.append("constraints ").append(std::to_string(maps.size())).append("\n");
  for (const input::ConstraintMap& map : maps) {
    out.append(map.kind == input::ConstraintKind::kMountainousness ? "mountainousness"
                                                                   : "riverSlope");
    for (const double v : {map.bounds.west, map.bounds.south, map.bounds.east, map.bounds.north}) {
      out.push_back(' ');
      appendNumber(out, v);
    }
    out.append(" ").append(std::to_string(map.image.width));
    out.append(" ").append(std::to_string(map.image.height));
    out.append(" ").append(pixelHash(map.image)).append("\n");
  }
}

void appendPoints(std::string& out, const std::vector<geometry::Vec2>& points) {
  out.append(std::to_string(points.size()));
  for (const geometry::Vec2 p : points) {
    out.push_back(' ');
    appendNumber(out, p.x);
    out.push_back(' ');
    appendNumber(out, p.y);
  }
}

void appendOptional(std::string& out, const std::optional<double>& value) {
  out.push_back(' ');
  if (value)
    appendNumber(out, *value);
  else
    out.push_back('-');
}

/// The drawn features, in file order; written only when there are some, so that worlds
/// without features keep the keys (and ETags) they had before features existed.
void appendFeatures(std::string& out, const input::Features& features) {
  if (features.empty())
    return;
  out.append("features ").append(std::to_string(features.mountains.size()));
  out.append(" ").append(std::to_string(features.ridges.size()));
  out.append(" ").append(std::to_string(features.rivers.size())).append("\n");
  for (const input::MountainFeature& m : features.mountains) {
    out.append("mountain ");
    appendPoints(out, {m.lonLat});
    appendOptional(out, m.elevation);
    appendOptional(out, m.radius);
    out.push_back('\n');
  }
  for (const input::RidgeFeature& r : features.ridges) {
    out.append("ridge ");
    appendPoints(out, r.lonLat);
    appendOptional(out, r.elevation);
    out.push_back('\n');
  }
  for (const input::RiverFeature& r : features.rivers) {
    out.append("river ");
    appendPoints(out, r.lonLat);
    out.push_back('\n');
    appendText(out, "name", r.name);
  }
}

} // namespace

std::string canonicalSpecText(const input::WorldSpec& spec, std::string_view generatorVersion) {
  std::string out = "strahler world spec 1\n";
  appendText(out, "generator", generatorVersion);
  appendText(out, "params", input::canonicalJson(spec.params));
  appendLand(out, spec.landLonLat);
  appendMouths(out, spec.mouths);
  appendConstraints(out, spec.constraints);
  appendFeatures(out, spec.features);
  return out;
}

std::string cacheKey(const input::WorldSpec& spec, std::string_view generatorVersion) {
  Hash128 hash;
  hash.add(canonicalSpecText(spec, generatorVersion));
  return hash.hex();
}

bool isValidCacheKey(std::string_view key) noexcept {
  if (key.empty() || key.size() > 128)
    return false;
  for (const char c : key) {
    const bool ok = (c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                    c == '_' || c == '-';
    if (!ok)
      return false;
  }
  return true;
}

} // namespace strahler::store
