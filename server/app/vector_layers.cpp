#include "vector_layers.h"

#include "strahler/geometry/web_mercator.h"
#include "strahler/render/contours.h"
#include "strahler/render/river_sections.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <optional>

namespace strahler::app {
namespace {

using geometry::Vec2;
using vector_tile::ClipBox;
using vector_tile::Feature;
using vector_tile::GeometryType;
using vector_tile::Layer;
using vector_tile::Point;

constexpr double kExtent = vector_tile::kDefaultExtent;
constexpr ClipBox kBox{-kVectorBuffer, kExtent + kVectorBuffer};

MercatorLine mercatorLine(std::span<const Vec2> local,
                          const geometry::LocalProjection& projection) {
  MercatorLine line;
  line.points.reserve(local.size());
  for (const Vec2 p : local)
    line.points.push_back(geometry::webMercatorUnit(projection.inverse(p)));
  for (const Vec2 p : line.points)
    line.box.add(p);
  return line;
}

/// mercatorLine() of a ring, with the boxes of its runs of edges.
MercatorLine mercatorRing(std::span<const Vec2> local,
                          const geometry::LocalProjection& projection) {
  MercatorLine ring = mercatorLine(local, projection);
  const std::size_t n = ring.points.size();
  for (std::size_t first = 0; first < n; first += kRingChunk) {
    geometry::Aabb box;
    for (std::size_t i = first; i <= std::min(first + kRingChunk, n); ++i)
      box.add(ring.points[i % n]); // the edge i-1 → i; the last run closes the ring
    ring.chunks.push_back(box);
  }
  return ring;
}

bool overlaps(const geometry::Aabb& a, const geometry::Aabb& b) noexcept {
  return a.min.x <= b.max.x && a.max.x >= b.min.x && a.min.y <= b.max.y && a.max.y >= b.min.y;
}

/// True when `p` is inside `ring` (crossing number, runs whose box misses p's row skipped).
bool ringContains(const MercatorLine& ring, Vec2 p) noexcept {
  const std::size_t n = ring.points.size();
  bool inside = false;
  for (std::size_t c = 0; c < ring.chunks.size(); ++c) {
    if (p.y < ring.chunks[c].min.y || p.y > ring.chunks[c].max.y)
      continue;
    for (std::size_t i = c * kRingChunk; i < std::min((c + 1) * kRingChunk, n); ++i) {
      const Vec2 a = ring.points[i], b = ring.points[(i + 1) % n];
      if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x))
        inside = !inside;
    }
  }
  return inside;
}

/// Tile units of normalised Web Mercator for one tile: tile = (m · 2^z − (x, y)) · extent.
class TileFrame {
public:
  explicit TileFrame(const geometry::TileId& tile)
      : scale_(std::ldexp(1.0, tile.z)), x_(static_cast<double>(tile.x)),
        y_(static_cast<double>(tile.y)) {
    const double margin = kVectorBuffer / kExtent;
    box_ = {{(x_ - margin) / scale_, (y_ - margin) / scale_},
            {(x_ + 1.0 + margin) / scale_, (y_ + 1.0 + margin) / scale_}};
  }

  /// True when `line`'s box meets the tile and its buffer.
  bool meets(const MercatorLine& line) const noexcept { return overlaps(line.box, box_); }
  /// For a ring whose boundary stays out of the tile and its buffer (no run's box meets
  /// them): whether it holds them; nullopt when its boundary may enter them.
  std::optional<bool> holds(const MercatorLine& ring) const noexcept {
    for (const geometry::Aabb& chunk : ring.chunks)
      if (overlaps(chunk, box_))
        return std::nullopt;
    return ringContains(ring, box_.center());
  }
  Vec2 toTile(Vec2 m) const noexcept {
    return {(m.x * scale_ - x_) * kExtent, (m.y * scale_ - y_) * kExtent};
  }
  std::vector<Vec2> toTile(std::span<const Vec2> line) const {
    std::vector<Vec2> out;
    out.reserve(line.size());
    for (const Vec2 p : line)
      out.push_back(toTile(p));
    return out;
  }

private:
  double scale_, x_, y_;
  geometry::Aabb box_;
};

/// The clipped lines of `line` (tile units), simplified within `tolerance`, as parts of a
/// feature.
void appendLines(std::span<const Vec2> line, std::vector<std::vector<Point>>& parts,
                 double tolerance = kVectorTolerance) {
  for (const auto& piece : vector_tile::clipLine(line, kBox)) {
    std::vector<Point> points = vector_tile::toTilePoints(piece, tolerance, false);
    if (points.size() >= 2)
      parts.push_back(std::move(points));
  }
}

/// `ring` (tile units) clipped and simplified, with the winding of `exterior`; empty when
/// nothing of it is left.
std::vector<Point> tileRing(std::span<const Vec2> ring, bool exterior) {
  std::vector<Point> points =
      vector_tile::toTilePoints(vector_tile::clipRing(ring, kBox), kVectorTolerance, true);
  const std::int64_t area = vector_tile::ringArea2(points);
  if (points.size() < 3 || area == 0)
    return {};
  if ((area > 0) != exterior)
    std::reverse(points.begin(), points.end());
  return points;
}

double round2(double v) {
  return std::round(v * 100.0) / 100.0;
}

} // namespace

WorldVectors projectWorldVectors(const construction::WorldData& world,
                                 const geometry::LocalProjection& projection) {
  WorldVectors out;
  render::forEachRiverSection(world, [&](const render::RiverSection& s) {
    out.rivers.push_back(
        {mercatorLine(s.line, projection), s.strahler, s.flow, s.widthDown, s.rosgen});
    out.maxOrder = std::max(out.maxOrder, s.strahler);
  });
  for (const geometry::Polygon& polygon : world.land) {
    MercatorPolygon p{mercatorRing(polygon.outer, projection), {}};
    for (const geometry::Ring& hole : polygon.holes)
      p.holes.push_back(mercatorRing(hole, projection));
    out.land.push_back(std::move(p));
  }
  out.features = &world.features;
  return out;
}

int minRiverOrder(int z, int maxOrder) noexcept {
  return std::min(std::max(13 - z, 1), maxOrder);
}

double contourInterval(int z) noexcept {
  if (z <= 7)
    return 1000.0;
  constexpr double kByZoom[] = {500.0, 200.0, 100.0, 100.0, 50.0, 20.0, 10.0, 10.0};
  return z >= 16 ? 5.0 : kByZoom[z - 8];
}

Layer riversLayer(const WorldVectors& world, const geometry::TileId& tile) {
  Layer layer{"rivers", vector_tile::kDefaultExtent, {}};
  const TileFrame frame(tile);
  const int minOrder = minRiverOrder(tile.z, world.maxOrder);
  for (const MercatorRiver& river : world.rivers) {
    if (river.order < minOrder || !frame.meets(river.line))
      continue;
    Feature f{GeometryType::kLineString, {}, {}, 0};
    appendLines(frame.toTile(river.line.points), f.parts);
    if (f.parts.empty())
      continue;
    f.properties = {{"order", std::int64_t{river.order}},
                    {"flow", round2(river.flow)},
                    {"width", round2(river.width)},
                    {"rosgen", std::string(primitives::riverTypeName(river.rosgen))}};
    layer.features.push_back(std::move(f));
  }
  return layer;
}

Layer waterLayer(const WorldVectors& world, const geometry::TileId& tile) {
  Layer layer{"water", vector_tile::kDefaultExtent, {}};
  const TileFrame frame(tile);
  const std::vector<Vec2> square = {
      {kBox.lo, kBox.lo}, {kBox.hi, kBox.lo}, {kBox.hi, kBox.hi}, {kBox.lo, kBox.hi}};
  const double squareArea = vector_tile::ringArea2(square);
  Feature sea{GeometryType::kPolygon, {}, {{"kind", std::string("sea")}}, 0};
  Feature lakes{GeometryType::kPolygon, {}, {{"kind", std::string("lake")}}, 0};
  bool allLand = false;
  for (const MercatorPolygon& polygon : world.land) {
    if (!frame.meets(polygon.outer))
      continue;
    // Far from the coast (most tiles of a large world) the ring is not clipped: it holds the
    // tile or misses it.
    if (const std::optional<bool> holds = frame.holds(polygon.outer); holds && !*holds)
      continue; // its holes are inside it
    else if (holds) {
      allLand = true;
    } else {
      const std::vector<Vec2> outer = frame.toTile(polygon.outer.points);
      const std::vector<Vec2> clipped = vector_tile::clipRing(outer, kBox);
      if (std::abs(vector_tile::ringArea2(clipped)) >= squareArea * (1.0 - 1e-9))
        allLand = true; // the coast is outside the tile and its buffer
      else if (std::vector<Point> ring = tileRing(outer, false); !ring.empty())
        sea.parts.push_back(std::move(ring));
    }
    for (const MercatorLine& hole : polygon.holes) {
      if (!frame.meets(hole))
        continue;
      const std::optional<bool> holds = frame.holds(hole);
      if (holds && !*holds)
        continue;
      std::vector<Point> ring = tileRing(holds ? square : frame.toTile(hole.points), true);
      if (!ring.empty())
        lakes.parts.push_back(std::move(ring));
    }
  }
  if (!allLand) {
    std::vector<Point> outline = tileRing(square, true);
    sea.parts.insert(sea.parts.begin(), std::move(outline));
    layer.features.push_back(std::move(sea));
  }
  if (!lakes.parts.empty())
    layer.features.push_back(std::move(lakes));
  return layer;
}

Layer featuresLayer(const WorldVectors& world, const geometry::TileId& tile) {
  Layer layer{"features", vector_tile::kDefaultExtent, {}};
  if (world.features == nullptr)
    return layer;
  const TileFrame frame(tile);
  const auto lineOf = [&](const std::vector<Vec2>& lonLat) {
    std::vector<Vec2> line;
    for (const Vec2 p : lonLat)
      line.push_back(frame.toTile(geometry::webMercatorUnit(p)));
    return line;
  };
  for (const input::MountainFeature& m : world.features->mountains) {
    const Vec2 p = frame.toTile(geometry::webMercatorUnit(m.lonLat));
    if (!kBox.contains(p))
      continue;
    Feature f{GeometryType::kPoint,
              {{Point{static_cast<std::int32_t>(std::lround(p.x)),
                      static_cast<std::int32_t>(std::lround(p.y))}}},
              {{"kind", std::string("mountain")}},
              0};
    if (m.elevation)
      f.properties.emplace_back("elevation", *m.elevation);
    if (m.radius)
      f.properties.emplace_back("radius", *m.radius);
    layer.features.push_back(std::move(f));
  }
  for (const input::RidgeFeature& r : world.features->ridges) {
    Feature f{GeometryType::kLineString, {}, {{"kind", std::string("ridge")}}, 0};
    appendLines(lineOf(r.lonLat), f.parts);
    if (r.elevation)
      f.properties.emplace_back("elevation", *r.elevation);
    if (!f.parts.empty())
      layer.features.push_back(std::move(f));
  }
  for (const input::RiverFeature& r : world.features->rivers) {
    Feature f{GeometryType::kLineString, {}, {{"kind", std::string("river")}}, 0};
    appendLines(lineOf(r.lonLat), f.parts);
    if (!r.name.empty())
      f.properties.emplace_back("name", r.name);
    if (!f.parts.empty())
      layer.features.push_back(std::move(f));
  }
  return layer;
}

Layer contoursLayer(std::span<const double> heights, int z) {
  Layer layer{"contours", vector_tile::kDefaultExtent, {}};
  constexpr int n = kContourGrid + 2;
  const auto [lo, hi] = std::minmax_element(heights.begin(), heights.end());
  if (lo == heights.end())
    return layer;
  const double interval = contourInterval(z);
  const std::vector<double> levels = render::contourLevels(std::max(*lo, 0.0), *hi, interval);
  // Bordered sample (i, j) is the centre of pixel (i − 1, j − 1): tile units (i − 0.5) · unit.
  const double unit = kExtent / kContourGrid;
  for (const render::ContourLine& c : render::traceContours(heights, n, n, levels)) {
    std::vector<Vec2> line;
    line.reserve(c.points.size() + 1);
    for (const Vec2 p : c.points)
      line.push_back({(p.x - 0.5) * unit, (p.y - 0.5) * unit});
    if (c.closed)
      line.push_back(line.front());
    Feature f{GeometryType::kLineString, {}, {}, 0};
    // Not simplified (only collinear points go): the grid already spaces the points 16 units
    // apart, and neighbours' lines then cross their shared edge at the same points.
    appendLines(line, f.parts, 0.0);
    if (f.parts.empty())
      continue;
    const auto elevation = static_cast<std::int64_t>(std::llround(c.elevation));
    const auto step = static_cast<std::int64_t>(std::llround(5.0 * interval));
    f.properties = {{"elevation", elevation}, {"index", elevation % step == 0}};
    layer.features.push_back(std::move(f));
  }
  return layer;
}

std::string vectorLayersJson(int minZoom, int maxZoom) {
  using nlohmann::json;
  const auto layer = [&](const char* name, json fields, const char* description) {
    return json{{"id", name},
                {"fields", std::move(fields)},
                {"minzoom", minZoom},
                {"maxzoom", maxZoom},
                {"description", description}};
  };
  return json::array({layer("water", {{"kind", "String: sea or lake"}}, "the sea and the lakes"),
                      layer("contours",
                            {{"elevation", "Number: m"}, {"index", "Boolean: every fifth level"}},
                            "isolines of the terrain above 0 m"),
                      layer("rivers",
                            {{"order", "Number: Strahler order"},
                             {"flow", "Number: m3/s at the downstream end"},
                             {"width", "Number: channel width at the downstream end, m"},
                             {"rosgen", "String: Rosgen type"}},
                            "the carved rivers, the orders visible at the zoom"),
                      layer("features",
                            {{"kind", "String: mountain, ridge or river"},
                             {"name", "String"},
                             {"elevation", "Number: m"},
                             {"radius", "Number: m"}},
                            "the artist's vector map")})
      .dump();
}

std::string vectorTileJson(const std::string& id, const std::string& base, double west,
                           double south, double east, double north, Vec2 center,
                           const std::string& version) {
  using nlohmann::json;
  const json layers = json::parse(vectorLayersJson(0, tiling::TileScheme::kMaxWebZoom));
  const json tj = {{"tilejson", "3.0.0"},
                   {"name", id},
                   {"description", "strahler vector tiles (Mapbox Vector Tile 2.1)"},
                   {"version", "1.0.0"},
                   {"scheme", "xyz"},
                   {"format", "pbf"},
                   {"tiles", {base + "/vector/{z}/{x}/{y}.mvt?v=" + version}},
                   {"minzoom", 0},
                   {"maxzoom", tiling::TileScheme::kMaxWebZoom},
                   {"bounds", {west, south, east, north}},
                   {"center", {center.x, center.y, 9}},
                   {"vector_layers", layers},
                   {"attribution", "strahler"}};
  return tj.dump();
}

} // namespace strahler::app
