// GeoJSON -> input::Features: the structure, kinds, properties and numbers. The geometric rules
// (land, mouths, crossings) are in feature_checks.cpp.
#include "feature_checks.h"
#include "json_util.h"

#include "strahler/base/guarded.h"
#include "strahler/input/feature_parser.h"

#include <cmath>
#include <exception>
#include <new>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace strahler::input {
namespace {

using base::ErrorCode;
using base::makeError;
using detail::Json;

/// Largest elevation a drawn feature may ask for (Everest is 8,849 m), m.
constexpr double kMaxElevation = 10'000.0;

/// What every message starts with; the labels of FeatureLabels go without it.
constexpr std::string_view kPrefix = "features: ";

std::string withoutPrefix(const std::string& where) {
  return where.substr(kPrefix.size());
}

class FeatureReader {
public:
  FeatureReader(const geometry::LocalProjection& projection, const InputLimits& limits)
      : projection_(projection), limits_(limits) {}

  base::Status readRoot(const Json& root) {
    if (!root.is_object())
      return makeError(ErrorCode::kInvalidInput,
                       std::string("features: expected a GeoJSON object, got ") +
                           detail::describeType(root));
    const auto type = root.find("type");
    if (type == root.end() || !type->is_string())
      return makeError(ErrorCode::kInvalidInput,
                       "features: missing \"type\" member; expected a GeoJSON FeatureCollection "
                       "or Feature");
    if (*type == "Feature")
      return readFeature(root, 0);
    if (*type != "FeatureCollection")
      return makeError(ErrorCode::kInvalidInput,
                       "features: type " + detail::printable(type->get<std::string>()) +
                           " is not a FeatureCollection or Feature (each feature needs a "
                           "\"kind\" property)");
    const auto features = root.find("features");
    if (features == root.end() || !features->is_array())
      return makeError(ErrorCode::kInvalidInput,
                       "features: FeatureCollection needs a \"features\" array");
    for (std::size_t i = 0; i < features->size(); ++i) {
      const Json& feature = (*features)[i];
      const auto ftype = feature.is_object() ? feature.find("type") : feature.end();
      if (!feature.is_object() || ftype == feature.end() || *ftype != "Feature")
        return makeError(ErrorCode::kInvalidInput,
                         "features: feature " + std::to_string(i) +
                             ": not a GeoJSON Feature (an object with \"type\": \"Feature\")");
      STRAHLER_RETURN_IF_ERROR(readFeature(feature, i));
    }
    return base::Ok{};
  }

  Features& features() noexcept { return features_; }
  detail::FeatureLabels& labels() noexcept { return labels_; }

private:
  base::Status readFeature(const Json& feature, std::size_t index) {
    std::string where = std::string(kPrefix) + "feature " + std::to_string(index);
    if (++featureCount_ > limits_.maxFeatures)
      return makeError(ErrorCode::kLimitExceeded, where + ": more than " +
                                                      std::to_string(limits_.maxFeatures) +
                                                      " features (limit maxFeatures)");
    const auto properties = feature.find("properties");
    if (properties == feature.end() || !properties->is_object())
      return makeError(ErrorCode::kInvalidInput,
                       where + ": \"properties\" must be an object with a \"kind\" (\"mountain\", "
                               "\"ridge\" or \"river\")");
    const auto kind = properties->find("kind");
    if (kind == properties->end())
      return makeError(ErrorCode::kInvalidInput,
                       where + ": no \"kind\" property (\"mountain\", \"ridge\" or \"river\")");
    if (!kind->is_string() || (*kind != "mountain" && *kind != "ridge" && *kind != "river"))
      return makeError(ErrorCode::kInvalidInput,
                       where + ": unknown kind " +
                           (kind->is_string()
                                ? "\"" + detail::printable(kind->get<std::string>()) + "\""
                                : std::string(detail::describeType(*kind))) +
                           "; expected \"mountain\", \"ridge\" or \"river\"");
    const std::string kindName = kind->get<std::string>();
    STRAHLER_RETURN_IF_ERROR(checkPropertyNames(*properties, kindName, where));
    const auto geometry = feature.find("geometry");
    if (geometry == feature.end() || !geometry->is_object())
      return makeError(ErrorCode::kInvalidInput, where + " (" + kindName + "): missing geometry");
    if (kindName == "mountain")
      return readMountain(*properties, *geometry, where);
    if (kindName == "ridge")
      return readRidge(*properties, *geometry, where);
    return readRiver(*properties, *geometry, where);
  }

  static base::Status checkPropertyNames(const Json& properties, const std::string& kind,
                                         const std::string& where) {
    for (const auto& [key, value] : properties.items()) {
      const bool allowed = key == "kind" || (key == "elevation" && kind != "river") ||
                           (key == "radius" && kind == "mountain") ||
                           (key == "name" && kind == "river");
      if (!allowed)
        return makeError(ErrorCode::kInvalidInput,
                         where + " (" + kind + "): unknown property \"" + detail::printable(key) +
                             "\"; a " + kind + " takes " +
                             (kind == "mountain" ? "\"elevation\" and \"radius\""
                              : kind == "ridge"  ? "\"elevation\""
                                                 : "\"name\"") +
                             " besides \"kind\"");
    }
    return base::Ok{};
  }

  /// An optional number property in (0, max]; `what` names it in messages.
  static base::Result<std::optional<double>> readPositive(const Json& properties, const char* key,
                                                          double max, const std::string& where) {
    const auto value = properties.find(key);
    if (value == properties.end() || value->is_null())
      return std::optional<double>();
    if (!value->is_number())
      return makeError(ErrorCode::kInvalidInput, where + ": \"" + key + "\" must be a number " +
                                                     "(metres), got " +
                                                     detail::describeType(*value));
    const double v = value->get<double>();
    if (!(std::isfinite(v) && v > 0.0 && v <= max))
      return makeError(ErrorCode::kOutOfRange, where + ": \"" + key + "\" " +
                                                   detail::formatNumber(v) + " m is outside (0, " +
                                                   detail::formatNumber(max) + "]");
    return std::optional<double>(v);
  }

  base::Result<const Json*> coordinates(const Json& geometry, const char* expected,
                                        const std::string& where) const {
    const auto type = geometry.find("type");
    if (type == geometry.end() || !type->is_string() || *type != expected)
      return makeError(ErrorCode::kInvalidInput,
                       where + ": geometry type " +
                           (type != geometry.end() && type->is_string()
                                ? detail::printable(type->get<std::string>())
                                : std::string("(none)")) +
                           " is not a " + expected);
    const auto coords = geometry.find("coordinates");
    if (coords == geometry.end())
      return makeError(ErrorCode::kInvalidInput,
                       where + ": " + expected + " needs \"coordinates\"");
    return &*coords;
  }

  base::Result<geometry::Vec2> readPoint(const Json& position, const std::string& where) {
    if (++vertexCount_ > limits_.maxFeatureVertices)
      return makeError(ErrorCode::kLimitExceeded,
                       where + ": more than " + std::to_string(limits_.maxFeatureVertices) +
                           " points in all features (limit maxFeatureVertices)");
    return detail::parsePosition(position, where);
  }

  base::Status readLine(const Json& geometry, const std::string& where,
                        std::vector<geometry::Vec2>& lonLat, std::vector<geometry::Vec2>& line) {
    STRAHLER_ASSIGN_OR_RETURN(const Json* coords, coordinates(geometry, "LineString", where));
    if (!coords->is_array() || coords->size() < 2)
      return makeError(ErrorCode::kInvalidInput,
                       where + ": a LineString needs an array of at least 2 positions");
    for (std::size_t k = 0; k < coords->size(); ++k) {
      const std::string point = where + ": point " + std::to_string(k);
      STRAHLER_ASSIGN_OR_RETURN(const geometry::Vec2 p, readPoint((*coords)[k], point));
      const geometry::Vec2 local = projection_.forward(p);
      if (!line.empty() && local == line.back())
        return makeError(ErrorCode::kInvalidInput, point + " at " + detail::lonLatText(p) +
                                                       " repeats point " + std::to_string(k - 1) +
                                                       "; remove it");
      lonLat.push_back(p);
      line.push_back(local);
    }
    return base::Ok{};
  }

  base::Status readMountain(const Json& properties, const Json& geometry, std::string where) {
    where += " (mountain)";
    MountainFeature mountain;
    STRAHLER_ASSIGN_OR_RETURN(mountain.elevation,
                              readPositive(properties, "elevation", kMaxElevation, where));
    STRAHLER_ASSIGN_OR_RETURN(
        mountain.radius, readPositive(properties, "radius", limits_.maxExtentKm * 1000.0, where));
    STRAHLER_ASSIGN_OR_RETURN(const Json* coords, coordinates(geometry, "Point", where));
    STRAHLER_ASSIGN_OR_RETURN(mountain.lonLat, readPoint(*coords, where));
    mountain.position = projection_.forward(mountain.lonLat);
    features_.mountains.push_back(mountain);
    labels_.mountains.push_back(withoutPrefix(where));
    return base::Ok{};
  }

  base::Status readRidge(const Json& properties, const Json& geometry, std::string where) {
    where += " (ridge)";
    RidgeFeature ridge;
    STRAHLER_ASSIGN_OR_RETURN(ridge.elevation,
                              readPositive(properties, "elevation", kMaxElevation, where));
    STRAHLER_RETURN_IF_ERROR(readLine(geometry, where, ridge.lonLat, ridge.line));
    features_.ridges.push_back(std::move(ridge));
    labels_.ridges.push_back(withoutPrefix(where));
    return base::Ok{};
  }

  base::Status readRiver(const Json& properties, const Json& geometry, std::string where) {
    RiverFeature river;
    const auto name = properties.find("name");
    if (name != properties.end() && !name->is_null()) {
      if (!name->is_string())
        return makeError(ErrorCode::kInvalidInput, where +
                                                       " (river): \"name\" must be a string, got " +
                                                       detail::describeType(*name));
      river.name = name->get<std::string>();
    }
    where += river.name.empty() ? " (river)" : " (river \"" + detail::printable(river.name) + "\")";
    STRAHLER_RETURN_IF_ERROR(readLine(geometry, where, river.lonLat, river.line));
    features_.rivers.push_back(std::move(river));
    labels_.rivers.push_back(withoutPrefix(where));
    return base::Ok{};
  }

  const geometry::LocalProjection& projection_;
  const InputLimits& limits_;
  std::size_t featureCount_ = 0;
  std::size_t vertexCount_ = 0;
  Features features_;
  detail::FeatureLabels labels_;
};

base::Result<Features> parseUnguarded(std::string_view geoJson,
                                      const geometry::LocalProjection& projection,
                                      const geometry::MultiPolygon& landLocal, const Params& params,
                                      const InputLimits& limits) {
  detail::JsonLimits jsonLimits;
  jsonLimits.maxBytes = limits.maxFileBytes;
  jsonLimits.maxDepth = limits.maxJsonDepth;
  // A feature costs a few values (feature, properties, geometry), a point three.
  jsonLimits.maxValues = detail::saturatingAdd(
      detail::saturatingAdd(detail::saturatingMul(16, limits.maxFeatures),
                            detail::saturatingMul(4, limits.maxFeatureVertices)),
      1u << 12);
  jsonLimits.valuesNote =
      "at most " + std::to_string(limits.maxFeatures) + " features (limit maxFeatures) of " +
      std::to_string(limits.maxFeatureVertices) + " points (limit maxFeatureVertices)";
  STRAHLER_ASSIGN_OR_RETURN(const Json root, detail::parseJson(geoJson, "features", jsonLimits));
  FeatureReader reader(projection, limits);
  STRAHLER_RETURN_IF_ERROR(reader.readRoot(root));
  STRAHLER_RETURN_IF_ERROR(
      detail::checkFeatures(reader.features(), reader.labels(), projection, landLocal, params));
  return std::move(reader.features());
}

} // namespace

FeatureTolerances featureTolerances(const Params& params) noexcept {
  return FeatureTolerances{0.25 * params.edgeLength, 1.5 * params.edgeLength};
}

base::Result<Features> parseFeatures(std::string_view geoJson,
                                     const geometry::LocalProjection& projection,
                                     const geometry::MultiPolygon& landLocal, const Params& params,
                                     const InputLimits& limits) {
  // An exception is a bug: the fuzz harness fails on the kInternal it becomes.
  return base::guarded(
      "features", [&] { return parseUnguarded(geoJson, projection, landLocal, params, limits); });
}

} // namespace strahler::input
