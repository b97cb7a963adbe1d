#include "strahler/input/world_spec.h"

#include "json_util.h"
#include "mouths.h"

#include "strahler/base/guarded.h"
#include "strahler/input/canonical_coastline.h"
#include "strahler/input/coastline.h"
#include "strahler/input/feature_parser.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <new>
#include <system_error>

namespace strahler::input {
namespace {

using base::ErrorCode;
using base::makeError;
namespace fs = std::filesystem;

std::string quoted(const std::string& path) {
  return "'" + path + "'";
}

std::string oneDecimal(double v) {
  std::array<char, 64> buffer{};
  std::snprintf(buffer.data(), buffer.size(), "%.1f", v);
  return buffer.data();
}

/// Reads a whole file of at most maxBytes; `what` names it in errors ("coastline file").
base::Result<std::string> readTextFile(const std::string& path, const std::string& what,
                                       std::size_t maxBytes) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (status.type() == fs::file_type::not_found)
    return makeError(ErrorCode::kNotFound, what + " " + quoted(path) + ": file not found");
  if (ec)
    return makeError(ErrorCode::kIoError, what + " " + quoted(path) + ": " + ec.message());
  if (fs::is_directory(status))
    return makeError(ErrorCode::kIoError, what + " " + quoted(path) + ": is a directory");
  const std::string tooBig = what + " " + quoted(path) + ": more than the limit of " +
                             std::to_string(maxBytes) + " bytes (limit maxFileBytes)";
  if (fs::is_regular_file(status)) {
    const std::uintmax_t size = fs::file_size(path, ec);
    if (!ec && size > maxBytes)
      return makeError(ErrorCode::kLimitExceeded, tooBig);
  }
  std::ifstream in(path, std::ios::binary);
  if (!in)
    return makeError(ErrorCode::kIoError, what + " " + quoted(path) + ": cannot open");
  std::string text;
  std::array<char, 1 << 16> chunk{};
  while (in) {
    in.read(chunk.data(), chunk.size());
    const auto got = static_cast<std::size_t>(in.gcount());
    if (text.size() + got > maxBytes)
      return makeError(ErrorCode::kLimitExceeded, tooBig);
    text.append(chunk.data(), got);
  }
  if (in.bad())
    return makeError(ErrorCode::kIoError, what + " " + quoted(path) + ": read failed");
  return text;
}

/// Errors in the content of a file get the file's path in front.
base::Error inFile(const std::string& path, base::Error error) {
  error.message = path + ": " + error.message;
  return error;
}

geometry::MultiPolygon project(const geometry::MultiPolygon& lonLat,
                               const geometry::LocalProjection& projection) {
  geometry::MultiPolygon out = lonLat;
  for (geometry::Polygon& polygon : out) {
    for (geometry::Vec2& v : polygon.outer)
      v = projection.forward(v);
    for (geometry::Ring& hole : polygon.holes)
      for (geometry::Vec2& v : hole)
        v = projection.forward(v);
  }
  return out;
}

/// Centres the projection on the land's area centroid (found in a first projection centred
/// on the bounding box), projects and orients the land, and checks its size.
base::Status projectLand(WorldSpec& spec, const InputLimits& limits) {
  const geometry::Vec2 boxCenter = geometry::bounds(spec.landLonLat).center();
  const geometry::LocalProjection rough(boxCenter.x, boxCenter.y);
  const geometry::Vec2 center = rough.inverse(geometry::centroid(project(spec.landLonLat, rough)));
  spec.projection = geometry::LocalProjection(center.x, center.y);
  spec.land = project(spec.landLonLat, spec.projection);
  for (geometry::Polygon& polygon : spec.land)
    geometry::orient(polygon);

  const geometry::Vec2 size = geometry::bounds(spec.land).size() / 1000.0;
  if (!(size.x <= limits.maxExtentKm && size.y <= limits.maxExtentKm))
    return makeError(ErrorCode::kLimitExceeded,
                     "coastline: the land measures " + oneDecimal(size.x) + " km x " +
                         oneDecimal(size.y) + " km, more than the limit of " +
                         oneDecimal(limits.maxExtentKm) +
                         " km on a side (raise it with --max-extent-km)");
  const double areaKm2 = spec.areaKm2();
  if (!(areaKm2 > 0.0))
    return makeError(ErrorCode::kInvalidInput, "coastline: the land has zero area");
  if (!(areaKm2 <= limits.maxAreaKm2))
    return makeError(ErrorCode::kLimitExceeded, "coastline: land area " + oneDecimal(areaKm2) +
                                                    " km² is more than the limit of " +
                                                    oneDecimal(limits.maxAreaKm2) +
                                                    " km² (raise it with --max-area-km2)");
  return base::Ok{};
}

base::Result<ConstraintMap> loadConstraint(const ConstraintSource& source, std::size_t index,
                                           const fs::path& baseDir, const geometry::Aabb& land,
                                           const InputLimits& limits) {
  const std::string where = "params: constraints[" + std::to_string(index) + "]: ";
  const GeoBounds& b = source.bounds;
  if (!(b.west <= land.max.x && b.east >= land.min.x && b.south <= land.max.y &&
        b.north >= land.min.y))
    return makeError(
        ErrorCode::kInvalidInput,
        where + "bounds [" + detail::formatNumber(b.west) + ", " + detail::formatNumber(b.south) +
            ", " + detail::formatNumber(b.east) + ", " + detail::formatNumber(b.north) +
            "] do not overlap the coastline, which lies within [" +
            detail::formatNumber(land.min.x) + ", " + detail::formatNumber(land.min.y) + ", " +
            detail::formatNumber(land.max.x) + ", " + detail::formatNumber(land.max.y) + "]");
  fs::path path(source.imagePath);
  if (path.is_relative() && !baseDir.empty())
    path = baseDir / path;
  auto image = image::readGrayImage(path.string(), limits.maxConstraintPixels);
  if (!image.ok()) {
    base::Error error = std::move(image).error();
    error.message = where + error.message;
    return error;
  }
  ConstraintMap map;
  map.kind = source.kind;
  map.bounds = source.bounds;
  map.image = std::move(image).value();
  const auto [lo, hi] = std::minmax_element(map.image.pixels.begin(), map.image.pixels.end());
  if (*lo < 0.0f || *hi > 1.0f)
    return makeError(ErrorCode::kOutOfRange, where + "image " + quoted(path.string()) +
                                                 " has values in [" + detail::formatNumber(*lo) +
                                                 ", " + detail::formatNumber(*hi) +
                                                 "]; constraint values must lie in [0, 1]");
  return map;
}

base::Result<WorldSpec> buildWorldSpec(std::string name, std::string_view coastGeoJson,
                                       const Params& params, const fs::path& imageDir,
                                       const InputLimits& limits, bool repair) {
  STRAHLER_RETURN_IF_ERROR(validateParams(params));
  WorldSpec spec;
  spec.name = std::move(name);
  spec.params = params;
  if (repair) {
    STRAHLER_ASSIGN_OR_RETURN(repair::RepairedCoast repaired,
                              parseAndRepairCoastline(coastGeoJson, limits));
    spec.landLonLat = std::move(repaired.land);
    spec.repairs = std::move(repaired.changes);
  } else {
    STRAHLER_ASSIGN_OR_RETURN(spec.landLonLat, parseCoastline(coastGeoJson, limits));
  }
  // The same land whichever way its rings run and wherever they start: one world, one key.
  canonicalizeCoastline(spec.landLonLat);
  spec.warnings = swappedCoordinateWarnings(spec.landLonLat);
  STRAHLER_RETURN_IF_ERROR(projectLand(spec, limits));
  const geometry::Aabb landBox = geometry::bounds(spec.landLonLat);
  for (std::size_t i = 0; i < params.constraints.size(); ++i) {
    STRAHLER_ASSIGN_OR_RETURN(ConstraintMap map,
                              loadConstraint(params.constraints[i], i, imageDir, landBox, limits));
    spec.constraints.push_back(std::move(map));
  }
  return spec;
}

base::Result<WorldSpec> loadWorldSpecUnguarded(const WorldSources& sources,
                                               const InputLimits& limits) {
  std::string coastText;
  std::string name = "default";
  if (!sources.coastPath.empty()) {
    STRAHLER_ASSIGN_OR_RETURN(
        coastText, readTextFile(sources.coastPath, "coastline file", limits.maxFileBytes));
    name = fs::path(sources.coastPath).stem().string();
    if (name.empty())
      name = "coastline";
  }
  Params params;
  fs::path imageDir;
  if (!sources.paramsPath.empty()) {
    STRAHLER_ASSIGN_OR_RETURN(const std::string paramsText,
                              readTextFile(sources.paramsPath, "params file", limits.maxFileBytes));
    auto parsed = parseParams(paramsText, limits);
    if (!parsed.ok())
      return inFile(sources.paramsPath, std::move(parsed).error());
    params = std::move(parsed).value();
    imageDir = fs::path(sources.paramsPath).parent_path();
  }
  if (sources.seed)
    params.seed = *sources.seed;
  const std::string_view coast =
      sources.coastPath.empty() ? defaultCoastlineGeoJson() : std::string_view(coastText);
  auto built = buildWorldSpec(std::move(name), coast, params, imageDir, limits, sources.repair);
  if (!built.ok()) {
    base::Error error = std::move(built).error();
    // Coastline faults are in the coastline file, constraint faults in the params file.
    if (!sources.coastPath.empty() && error.message.rfind("coastline:", 0) == 0)
      return inFile(sources.coastPath, std::move(error));
    if (!sources.paramsPath.empty() && error.message.rfind("params:", 0) == 0)
      return inFile(sources.paramsPath, std::move(error));
    return error;
  }
  WorldSpec spec = std::move(built).value();
  if (!sources.mouthsPath.empty()) {
    STRAHLER_ASSIGN_OR_RETURN(const std::string mouthsText,
                              readTextFile(sources.mouthsPath, "mouths file", limits.maxFileBytes));
    auto mouths = detail::parseMouths(mouthsText, spec.projection, limits);
    if (!mouths.ok())
      return inFile(sources.mouthsPath, std::move(mouths).error());
    spec.mouths = std::move(mouths).value();
  }
  if (!sources.featuresPath.empty()) {
    STRAHLER_ASSIGN_OR_RETURN(
        const std::string featuresText,
        readTextFile(sources.featuresPath, "features file", limits.maxFileBytes));
    auto features = parseFeatures(featuresText, spec.projection, spec.land, spec.params, limits);
    if (!features.ok())
      return inFile(sources.featuresPath, std::move(features).error());
    spec.features = std::move(features).value();
  }
  return spec;
}

} // namespace

std::optional<double> ConstraintMap::sample(geometry::Vec2 lonLat) const noexcept {
  if (!(lonLat.x >= bounds.west && lonLat.x <= bounds.east && lonLat.y >= bounds.south &&
        lonLat.y <= bounds.north))
    return std::nullopt;
  if (image.width <= 0 || image.height <= 0 || !(bounds.west < bounds.east) ||
      !(bounds.south < bounds.north))
    return std::nullopt;
  const double u = (lonLat.x - bounds.west) / (bounds.east - bounds.west);
  const double v = (bounds.north - lonLat.y) / (bounds.north - bounds.south);
  return static_cast<double>(image.sample(u, v));
}

double WorldSpec::areaKm2() const noexcept {
  return geometry::area(land) / 1e6;
}

std::optional<double> WorldSpec::constraintAt(ConstraintKind kind,
                                              geometry::Vec2 local) const noexcept {
  const geometry::Vec2 lonLat = projection.inverse(local);
  for (const ConstraintMap& map : constraints)
    if (map.kind == kind)
      if (auto value = map.sample(lonLat))
        return value;
  return std::nullopt;
}

base::Result<WorldSpec> makeWorldSpec(std::string name, std::string_view coastGeoJson,
                                      const Params& params, const InputLimits& limits,
                                      bool repair) {
  return base::guarded("world", [&] {
    return buildWorldSpec(std::move(name), coastGeoJson, params, fs::path(), limits, repair);
  });
}

base::Result<WorldSpec> loadWorldSpec(const WorldSources& sources, const InputLimits& limits) {
  return base::guarded("world", [&] { return loadWorldSpecUnguarded(sources, limits); });
}

} // namespace strahler::input
