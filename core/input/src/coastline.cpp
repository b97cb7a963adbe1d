// GeoJSON structure -> rings. The topology checks (crossings, holes, overlaps) are in
// ring_validation.cpp.
#include "strahler/input/coastline.h"

#include "json_util.h"
#include "ring_validation.h"

#include "strahler/base/guarded.h"

#include <algorithm>
#include <exception>
#include <new>

namespace strahler::input {
namespace {

using base::ErrorCode;
using base::makeError;
using detail::Json;
using detail::ParsedPolygon;
using detail::ParsedRing;

/// Invalid-input errors of the topology checks are all defects the repair mends.
base::Status withRepairHint(base::Status status) {
  if (status.ok() || status.error().code != ErrorCode::kInvalidInput)
    return status;
  base::Error error = std::move(status).error();
  error.message += "; run with --repair to mend it";
  return error;
}

/// Parses every ring of a coastline, counting vertices and rings against the limits.
class CoastlineReader {
public:
  /// `raw`: keep rings exactly as given (for the repair) instead of dropping repeated
  /// positions and refusing spikes.
  CoastlineReader(const InputLimits& limits, bool raw) : limits_(limits), raw_(raw) {}

  base::Status readRoot(const Json& root) {
    if (!root.is_object())
      return makeError(ErrorCode::kInvalidInput,
                       std::string("coastline: expected a GeoJSON object, got ") +
                           detail::describeType(root));
    const auto type = root.find("type");
    if (type == root.end() || !type->is_string())
      return makeError(ErrorCode::kInvalidInput,
                       "coastline: missing \"type\" member; expected a GeoJSON Polygon, "
                       "MultiPolygon, Feature or FeatureCollection");
    const std::string& name = type->get_ref<const std::string&>();
    if (name == "FeatureCollection")
      return readCollection(root);
    if (name == "Feature")
      return readFeature(root, "feature 0");
    return readGeometry(root, "");
  }

  std::vector<ParsedPolygon>& polygons() noexcept { return polygons_; }

private:
  static std::string join(const std::string& prefix, const std::string& part) {
    return prefix.empty() ? part : prefix + ", " + part;
  }

  base::Status readCollection(const Json& root) {
    const auto features = root.find("features");
    if (features == root.end() || !features->is_array())
      return makeError(ErrorCode::kInvalidInput,
                       "coastline: FeatureCollection needs a \"features\" array");
    if (features->empty())
      return makeError(ErrorCode::kInvalidInput, "coastline: FeatureCollection has no features");
    for (std::size_t i = 0; i < features->size(); ++i) {
      const std::string where = "feature " + std::to_string(i);
      const Json& feature = (*features)[i];
      const auto type = feature.is_object() ? feature.find("type") : feature.end();
      if (!feature.is_object() || type == feature.end() || *type != "Feature")
        return makeError(ErrorCode::kInvalidInput, "coastline: " + where +
                                                       ": not a GeoJSON Feature (an object with "
                                                       "\"type\": \"Feature\")");
      STRAHLER_RETURN_IF_ERROR(readFeature(feature, where));
    }
    return base::Ok{};
  }

  base::Status readFeature(const Json& feature, const std::string& where) {
    const auto geometry = feature.find("geometry");
    if (geometry == feature.end())
      return makeError(ErrorCode::kInvalidInput, "coastline: " + where + ": missing geometry");
    if (geometry->is_null())
      return makeError(ErrorCode::kInvalidInput, "coastline: " + where + ": geometry is null");
    return readGeometry(*geometry, where);
  }

  base::Status readGeometry(const Json& geometry, const std::string& where) {
    const std::string at = where.empty() ? "coastline: " : "coastline: " + where + ": ";
    const auto type = geometry.is_object() ? geometry.find("type") : geometry.end();
    if (!geometry.is_object() || type == geometry.end() || !type->is_string())
      return makeError(ErrorCode::kInvalidInput,
                       at + "geometry must be an object with a \"type\" string");
    const std::string& name = type->get_ref<const std::string&>();
    if (name != "Polygon" && name != "MultiPolygon")
      return makeError(ErrorCode::kInvalidInput, at + "geometry type " + detail::printable(name) +
                                                     " is not a Polygon or MultiPolygon");
    const auto coordinates = geometry.find("coordinates");
    if (coordinates == geometry.end() || !coordinates->is_array())
      return makeError(ErrorCode::kInvalidInput, at + name + " needs a \"coordinates\" array");
    if (name == "Polygon")
      return readPolygon(*coordinates, join(where, "polygon 0"));
    if (coordinates->empty())
      return makeError(ErrorCode::kInvalidInput, at + "MultiPolygon has no polygons");
    for (std::size_t p = 0; p < coordinates->size(); ++p)
      STRAHLER_RETURN_IF_ERROR(
          readPolygon((*coordinates)[p], join(where, "polygon " + std::to_string(p))));
    return base::Ok{};
  }

  base::Status readPolygon(const Json& rings, const std::string& label) {
    if (!rings.is_array())
      return makeError(ErrorCode::kInvalidInput, "coastline: " + label +
                                                     ": a polygon must be an array of rings, got " +
                                                     detail::describeType(rings));
    if (rings.empty())
      return makeError(ErrorCode::kInvalidInput, "coastline: " + label + ": polygon has no rings");
    ParsedPolygon polygon;
    polygon.label = label;
    for (std::size_t r = 0; r < rings.size(); ++r) {
      auto ring = readRing(rings[r], "coastline: " + label + ", ring " + std::to_string(r));
      if (!ring.ok())
        return std::move(ring).error();
      polygon.rings.push_back(std::move(ring).value());
    }
    polygons_.push_back(std::move(polygon));
    return base::Ok{};
  }

  base::Result<ParsedRing> readRing(const Json& positions, const std::string& where) {
    if (!positions.is_array())
      return makeError(ErrorCode::kInvalidInput,
                       where + ": a ring must be an array of positions, got " +
                           detail::describeType(positions));
    const std::size_t n = positions.size();
    if (n < 4)
      return makeError(ErrorCode::kInvalidInput, where + ": ring has " + std::to_string(n) +
                                                     " positions, a ring needs at least 4");
    if (++rings_ > limits_.maxRings)
      return makeError(ErrorCode::kLimitExceeded, where + ": the coastline has more than " +
                                                      std::to_string(limits_.maxRings) +
                                                      " rings (limit maxRings)");
    if (n - 1 > limits_.maxVertices - std::min(vertices_, limits_.maxVertices))
      return makeError(ErrorCode::kLimitExceeded, where + ": the coastline has more than " +
                                                      std::to_string(limits_.maxVertices) +
                                                      " vertices (limit maxVertices)");
    vertices_ += n - 1;

    ParsedRing ring;
    ring.vertices.reserve(n - 1);
    ring.positions.reserve(n - 1);
    geometry::Vec2 first;
    for (std::size_t i = 0; i < n; ++i) {
      auto p = detail::parsePosition(positions[i], where + ", position " + std::to_string(i));
      if (!p.ok())
        return std::move(p).error();
      const geometry::Vec2 v = p.value();
      if (i == 0)
        first = v;
      if (i + 1 == n) {
        if (!(v == first))
          return makeError(ErrorCode::kInvalidInput,
                           where + ": ring not closed: the last position (" +
                               detail::formatNumber(v.x) + ", " + detail::formatNumber(v.y) +
                               ") differs from the first (" + detail::formatNumber(first.x) + ", " +
                               detail::formatNumber(first.y) + ")");
        break;
      }
      if (!raw_ && !ring.vertices.empty() && ring.vertices.back() == v)
        continue; // repeated position
      ring.vertices.push_back(v);
      ring.positions.push_back(static_cast<std::uint32_t>(i));
    }
    ring.closingPosition = static_cast<std::uint32_t>(n - 1);
    if (raw_)
      return ring;
    while (ring.vertices.size() > 1 && ring.vertices.back() == ring.vertices.front()) {
      ring.vertices.pop_back();
      ring.positions.pop_back();
    }
    STRAHLER_RETURN_IF_ERROR(withRepairHint(detail::checkRingShape(ring, where)));
    return ring;
  }

  const InputLimits& limits_;
  const bool raw_;
  std::vector<ParsedPolygon> polygons_;
  std::size_t vertices_ = 0;
  std::size_t rings_ = 0;
};

/// Refuses coastlines that cross the antimeridian: their rings would wrap the planet.
base::Status checkLongitudeSpan(const std::vector<ParsedPolygon>& polygons) {
  double west = 180.0, east = -180.0;
  for (const ParsedPolygon& p : polygons)
    for (const ParsedRing& r : p.rings)
      for (const geometry::Vec2& v : r.vertices) {
        west = std::min(west, v.x);
        east = std::max(east, v.x);
      }
  if (east - west > 180.0)
    return makeError(ErrorCode::kUnsupported,
                     "coastline: longitudes span " + detail::formatNumber(east - west) +
                         " degrees (from " + detail::formatNumber(west) + " to " +
                         detail::formatNumber(east) +
                         "); coastlines crossing the antimeridian (180 degrees) are not "
                         "supported: shift the longitudes of one side by 360");
  return base::Ok{};
}

/// The JSON, its structure and the longitude span: everything but the topology.
base::Result<std::vector<ParsedPolygon>> readPolygons(std::string_view geojson,
                                                      const InputLimits& limits, bool raw) {
  detail::JsonLimits jsonLimits;
  jsonLimits.maxBytes = limits.maxFileBytes;
  jsonLimits.maxDepth = limits.maxJsonDepth;
  // A position costs at most 4 JSON values (the array and up to 3 numbers).
  jsonLimits.maxValues = detail::saturatingAdd(
      detail::saturatingMul(4, detail::saturatingAdd(limits.maxVertices, limits.maxRings)),
      1u << 16);
  jsonLimits.valuesNote = "the coastline is limited to " + std::to_string(limits.maxVertices) +
                          " vertices (limit maxVertices)";
  STRAHLER_ASSIGN_OR_RETURN(const Json root, detail::parseJson(geojson, "coastline", jsonLimits));
  CoastlineReader reader(limits, raw);
  STRAHLER_RETURN_IF_ERROR(reader.readRoot(root));
  std::vector<ParsedPolygon>& polygons = reader.polygons();
  STRAHLER_RETURN_IF_ERROR(checkLongitudeSpan(polygons));
  return std::move(polygons);
}

base::Status checkTopology(const std::vector<ParsedPolygon>& polygons) {
  std::size_t vertexCount = 0;
  for (const ParsedPolygon& p : polygons)
    for (const ParsedRing& r : p.rings)
      vertexCount += r.vertices.size();
  const std::uint64_t maxPairTests = 50'000'000u + 64u * std::uint64_t{vertexCount};
  return detail::checkTopology(polygons, maxPairTests);
}

base::Result<geometry::MultiPolygon> parseCoastlineUnguarded(std::string_view geojson,
                                                             const InputLimits& limits) {
  STRAHLER_ASSIGN_OR_RETURN(std::vector<ParsedPolygon> polygons,
                            readPolygons(geojson, limits, false));
  STRAHLER_RETURN_IF_ERROR(withRepairHint(checkTopology(polygons)));
  geometry::MultiPolygon result;
  result.reserve(polygons.size());
  for (ParsedPolygon& p : polygons) {
    geometry::Polygon polygon;
    polygon.outer = std::move(p.rings[0].vertices);
    for (std::size_t h = 1; h < p.rings.size(); ++h)
      polygon.holes.push_back(std::move(p.rings[h].vertices));
    result.push_back(std::move(polygon));
  }
  return result;
}

/// The repaired land as parsed rings (positions: vertex indices), for the usual checks.
std::vector<ParsedPolygon> asParsed(const geometry::MultiPolygon& land) {
  std::vector<ParsedPolygon> polygons;
  for (std::size_t p = 0; p < land.size(); ++p) {
    ParsedPolygon polygon;
    polygon.label = "repaired polygon " + std::to_string(p);
    auto add = [&](const geometry::Ring& vertices) {
      ParsedRing ring;
      ring.vertices = vertices;
      for (std::uint32_t i = 0; i < vertices.size(); ++i)
        ring.positions.push_back(i);
      ring.closingPosition = static_cast<std::uint32_t>(vertices.size());
      polygon.rings.push_back(std::move(ring));
    };
    add(land[p].outer);
    for (const geometry::Ring& hole : land[p].holes)
      add(hole);
    polygons.push_back(std::move(polygon));
  }
  return polygons;
}

base::Result<repair::RepairedCoast> parseAndRepairUnguarded(std::string_view geojson,
                                                            const InputLimits& limits) {
  STRAHLER_ASSIGN_OR_RETURN(std::vector<ParsedPolygon> parsed, readPolygons(geojson, limits, true));
  std::vector<repair::InputPolygon> input;
  input.reserve(parsed.size());
  for (ParsedPolygon& p : parsed) {
    repair::InputPolygon polygon;
    polygon.label = std::move(p.label);
    for (ParsedRing& ring : p.rings)
      polygon.rings.push_back(std::move(ring.vertices));
    input.push_back(std::move(polygon));
  }
  STRAHLER_ASSIGN_OR_RETURN(repair::RepairedCoast repaired, repair::repairCoastline(input));
  const std::vector<ParsedPolygon> check = asParsed(repaired.land);
  base::Status valid = base::Ok{};
  for (const ParsedPolygon& p : check)
    for (std::size_t r = 0; r < p.rings.size() && valid.ok(); ++r)
      valid = detail::checkRingShape(p.rings[r],
                                     "coastline: " + p.label + ", ring " + std::to_string(r));
  if (valid.ok())
    valid = checkTopology(check);
  if (!valid.ok()) {
    base::Error error = std::move(valid).error();
    error.message = "coastline: the repair left a defect (a bug in strahler; please report "
                    "it): " +
                    error.message;
    return error;
  }
  return repaired;
}

} // namespace

base::Result<geometry::MultiPolygon> parseCoastline(std::string_view geojson,
                                                    const InputLimits& limits) {
  return base::guarded("coastline", [&] { return parseCoastlineUnguarded(geojson, limits); });
}

base::Result<repair::RepairedCoast> parseAndRepairCoastline(std::string_view geojson,
                                                            const InputLimits& limits) {
  return base::guarded("coastline", [&] { return parseAndRepairUnguarded(geojson, limits); });
}

} // namespace strahler::input
