#include "mouths.h"

#include "json_util.h"

#include <cmath>
#include <limits>

namespace strahler::input::detail {
namespace {

using base::ErrorCode;
using base::makeError;

class MouthReader {
public:
  MouthReader(const geometry::LocalProjection& projection, const InputLimits& limits)
      : projection_(projection), limits_(limits) {}

  base::Status readRoot(const Json& root) {
    if (!root.is_object())
      return makeError(ErrorCode::kInvalidInput,
                       std::string("mouths: expected a GeoJSON object, got ") + describeType(root));
    const auto type = root.find("type");
    if (type == root.end() || !type->is_string())
      return makeError(ErrorCode::kInvalidInput,
                       "mouths: missing \"type\" member; expected a GeoJSON FeatureCollection, "
                       "Feature, Point or MultiPoint");
    if (*type == "FeatureCollection")
      return readCollection(root);
    if (*type == "Feature")
      return readFeature(root, "feature 0");
    return readGeometry(root, "", 1);
  }

  std::vector<UserMouth>& mouths() noexcept { return mouths_; }

private:
  base::Status readCollection(const Json& root) {
    const auto features = root.find("features");
    if (features == root.end() || !features->is_array())
      return makeError(ErrorCode::kInvalidInput,
                       "mouths: FeatureCollection needs a \"features\" array");
    if (features->empty())
      return makeError(ErrorCode::kInvalidInput, "mouths: FeatureCollection has no features");
    for (std::size_t i = 0; i < features->size(); ++i) {
      const Json& feature = (*features)[i];
      const std::string where = "feature " + std::to_string(i);
      const auto type = feature.is_object() ? feature.find("type") : feature.end();
      if (!feature.is_object() || type == feature.end() || *type != "Feature")
        return makeError(ErrorCode::kInvalidInput,
                         "mouths: " + where +
                             ": not a GeoJSON Feature (an object with \"type\": \"Feature\")");
      STRAHLER_RETURN_IF_ERROR(readFeature(feature, where));
    }
    return base::Ok{};
  }

  base::Status readFeature(const Json& feature, const std::string& where) {
    int priority = 1;
    const auto properties = feature.find("properties");
    if (properties != feature.end() && !properties->is_null()) {
      if (!properties->is_object())
        return makeError(ErrorCode::kInvalidInput,
                         "mouths: " + where + ": \"properties\" must be an object or null");
      const auto value = properties->find("priority");
      if (value != properties->end()) {
        STRAHLER_ASSIGN_OR_RETURN(priority, readPriority(*value, where));
      }
    }
    const auto geometry = feature.find("geometry");
    if (geometry == feature.end() || geometry->is_null())
      return makeError(ErrorCode::kInvalidInput, "mouths: " + where + ": missing geometry");
    return readGeometry(*geometry, where, priority);
  }

  static base::Result<int> readPriority(const Json& value, const std::string& where) {
    const std::string rule = "must be an integer >= 1";
    if (!value.is_number())
      return makeError(ErrorCode::kInvalidInput,
                       "mouths: " + where + ": priority " + rule + ", got " + describeType(value));
    const double v = value.get<double>();
    if (v != std::floor(v))
      return makeError(ErrorCode::kInvalidInput,
                       "mouths: " + where + ": priority " + formatNumber(v) + " " + rule);
    if (!(v >= 1.0 && v <= std::numeric_limits<int>::max()))
      return makeError(ErrorCode::kOutOfRange,
                       "mouths: " + where + ": priority " + formatNumber(v) + " " + rule);
    return static_cast<int>(v);
  }

  base::Status readGeometry(const Json& geometry, const std::string& where, int priority) {
    const std::string at = where.empty() ? "mouths: " : "mouths: " + where + ": ";
    const auto type = geometry.is_object() ? geometry.find("type") : geometry.end();
    if (!geometry.is_object() || type == geometry.end() || !type->is_string())
      return makeError(ErrorCode::kInvalidInput,
                       at + "geometry must be an object with a \"type\" string");
    const std::string& name = type->get_ref<const std::string&>();
    if (name != "Point" && name != "MultiPoint")
      return makeError(ErrorCode::kInvalidInput, at + "geometry type " + detail::printable(name) +
                                                     " is not a Point or MultiPoint");
    const auto coordinates = geometry.find("coordinates");
    if (coordinates == geometry.end())
      return makeError(ErrorCode::kInvalidInput, at + name + " needs \"coordinates\"");
    if (name == "Point")
      return addMouth(*coordinates, at + "point 0", priority);
    if (!coordinates->is_array())
      return makeError(ErrorCode::kInvalidInput,
                       at + "MultiPoint coordinates must be an array of positions");
    for (std::size_t i = 0; i < coordinates->size(); ++i)
      STRAHLER_RETURN_IF_ERROR(
          addMouth((*coordinates)[i], at + "point " + std::to_string(i), priority));
    return base::Ok{};
  }

  base::Status addMouth(const Json& position, const std::string& where, int priority) {
    if (mouths_.size() >= limits_.maxMouths)
      return makeError(ErrorCode::kLimitExceeded, where + ": more than " +
                                                      std::to_string(limits_.maxMouths) +
                                                      " mouths (limit maxMouths)");
    STRAHLER_ASSIGN_OR_RETURN(const geometry::Vec2 lonLat, parsePosition(position, where));
    mouths_.push_back(UserMouth{lonLat, projection_.forward(lonLat), priority});
    return base::Ok{};
  }

  const geometry::LocalProjection& projection_;
  const InputLimits& limits_;
  std::vector<UserMouth> mouths_;
};

} // namespace

base::Result<std::vector<UserMouth>> parseMouths(std::string_view geojson,
                                                 const geometry::LocalProjection& projection,
                                                 const InputLimits& limits) {
  JsonLimits jsonLimits;
  jsonLimits.maxBytes = limits.maxFileBytes;
  jsonLimits.maxDepth = limits.maxJsonDepth;
  // A mouth costs a few values (feature, properties, geometry, position): allow 16 each.
  jsonLimits.maxValues = saturatingAdd(saturatingMul(16, limits.maxMouths), 1u << 12);
  jsonLimits.valuesNote =
      "at most " + std::to_string(limits.maxMouths) + " mouths (limit maxMouths)";
  STRAHLER_ASSIGN_OR_RETURN(const Json root, parseJson(geojson, "mouths", jsonLimits));
  MouthReader reader(projection, limits);
  STRAHLER_RETURN_IF_ERROR(reader.readRoot(root));
  return std::move(reader.mouths());
}

} // namespace strahler::input::detail
