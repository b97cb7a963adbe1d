#pragma once

#include "strahler/base/result.h"
#include "strahler/geometry/polygon.h"
#include "strahler/geometry/projection.h"
#include "strahler/image/image.h"
#include "strahler/input/features.h"
#include "strahler/input/limits.h"
#include "strahler/input/params.h"
#include "strahler/repair/coast_repair.h"

#include <optional>
#include <string>
#include <vector>

namespace strahler::input {

/// A user constraint image placed on the map by its geographic bounds.
struct ConstraintMap {
  ConstraintKind kind = ConstraintKind::kMountainousness;
  GeoBounds bounds;
  image::GrayImage image; ///< Values in [0, 1].
  /// Value at (lon, lat) in degrees, bilinear; nullopt outside the bounds.
  std::optional<double> sample(geometry::Vec2 lonLat) const noexcept;
};

/// A river mouth given by the user, which replaces automatic mouth placement.
struct UserMouth {
  geometry::Vec2 lonLat;   ///< As given.
  geometry::Vec2 position; ///< In the local frame, not yet snapped to the coast.
  int priority = 1;        ///< ≥ 1; higher grows first (Section 4.2.1).
};

/// Everything that determines a world: land, parameters, seed, constraints.
struct WorldSpec {
  std::string name; ///< Human name (file stem or "default").
  /// Validated coastline, degrees, in canonical form (canonicalizeCoastline): the world and
  /// its cache key do not depend on the rings' winding, start vertex or order.
  geometry::MultiPolygon landLonLat;
  geometry::LocalProjection projection; ///< Centred on the land's centroid.
  geometry::MultiPolygon land;          ///< Local metres, outer rings CCW, holes CW.
  Params params;
  std::vector<UserMouth> mouths;
  std::vector<ConstraintMap> constraints;
  Features features; ///< The artist's vector map (--features); empty when none.
  /// What --repair changed in the coastline (empty without it, or when nothing needed it).
  /// landLonLat is the repaired coastline, so the cache key follows the repaired geometry.
  std::vector<repair::Change> repairs;
  /// Doubts about the input that do not stop it, one sentence each (coordinates that look
  /// swapped: swappedCoordinateWarnings).
  std::vector<std::string> warnings;

  /// Land area in km².
  double areaKm2() const noexcept;
  /// Value of the first constraint of `kind` at a local point, if one covers it.
  std::optional<double> constraintAt(ConstraintKind kind, geometry::Vec2 local) const noexcept;
};

/// Where a world's inputs come from; empty strings mean "not given".
struct WorldSources {
  std::string coastPath;    ///< GeoJSON file; empty: the embedded default island.
  std::string paramsPath;   ///< params JSON file; empty: defaults.
  std::string mouthsPath;   ///< GeoJSON Points with a "priority" property; empty: automatic.
  std::string featuresPath; ///< The artist's vector map (parseFeatures); empty: none.
  std::optional<std::uint64_t> seed; ///< Overrides params' seed when set.
  bool repair = false; ///< Mend the coastline's topology defects instead of refusing them.
};

/// Reads, validates and projects every input named by `sources`. Constraint images are
/// listed in the params JSON under "constraints" (paths relative to the params file).
/// With `sources.repair` the coastline is read by parseAndRepairCoastline and the changes are
/// listed in WorldSpec::repairs. Missing files are kNotFound and unreadable ones kIoError, naming
/// the path; faults inside a file are prefixed with its path. Mouths: a GeoJSON FeatureCollection
/// (or one Feature) of Point or MultiPoint geometries with an optional integer "priority" property
/// ≥ 1. Features: see parseFeatures (feature_parser.h). The land must measure at most
/// limits.maxExtentKm on each side of its bounding box and limits.maxAreaKm2 in area
/// (kLimitExceeded, giving both numbers).
base::Result<WorldSpec> loadWorldSpec(const WorldSources& sources, const InputLimits& limits = {});

/// Builds a spec from in-memory inputs (coastline GeoJSON in degrees, parsed params, which
/// are validated again); constraint image paths are taken relative to the working directory.
/// `repair` as WorldSources::repair.
base::Result<WorldSpec> makeWorldSpec(std::string name, std::string_view coastGeoJson,
                                      const Params& params, const InputLimits& limits = {},
                                      bool repair = false);

} // namespace strahler::input
