// The geometric rules of drawn features: mountains on land, rivers on land from source to a
// shore, no river crossing itself, another river or a ridge, mouths spaced as automatic ones.
#include "feature_checks.h"

#include "json_util.h"

#include "strahler/geometry/distance.h"
#include "strahler/geometry/grid_index.h"
#include "strahler/geometry/polygon_index.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <utility>

namespace strahler::input::detail {
namespace {

using base::ErrorCode;
using base::makeError;
using geometry::Vec2;

std::string kmText(double metres) {
  std::array<char, 32> buffer{};
  std::snprintf(buffer.data(), buffer.size(), "%.2f km", metres / 1000.0);
  return buffer.data();
}

class FeatureChecker {
public:
  FeatureChecker(const Features& features, const FeatureLabels& labels,
                 const geometry::LocalProjection& projection,
                 const geometry::MultiPolygon& landLocal, const Params& params)
      : features_(features), labels_(labels), projection_(projection), land_(landLocal),
        params_(params), tolerances_(featureTolerances(params)) {}

  base::Status run() {
    for (std::size_t i = 0; i < features_.mountains.size(); ++i) {
      const MountainFeature& m = features_.mountains[i];
      if (!land_.contains(m.position))
        return makeError(ErrorCode::kInvalidInput, "features: " + labels_.mountains[i] +
                                                       ": the mountain at " + lonLatText(m.lonLat) +
                                                       " lies off the land (in the sea or a lake)");
    }
    for (std::size_t i = 0; i < features_.rivers.size(); ++i)
      STRAHLER_RETURN_IF_ERROR(checkRiverOnLand(i));
    STRAHLER_RETURN_IF_ERROR(checkCrossings());
    return checkMouthSpacing();
  }

private:
  base::Error riverError(std::size_t i, const std::string& what) const {
    return makeError(ErrorCode::kInvalidInput, "features: " + labels_.rivers[i] + ": " + what);
  }

  /// True when p lies on the land or within `tolerance` of it.
  bool nearLand(Vec2 p, double tolerance) const noexcept {
    return land_.contains(p) || land_.distanceToBoundary(p, tolerance) < tolerance;
  }

  base::Status checkRiverOnLand(std::size_t i) const {
    const std::vector<Vec2>& line = features_.rivers[i].line;
    const std::vector<Vec2>& lonLat = features_.rivers[i].lonLat;
    const Vec2 mouth = line.back();
    const double mouthTolerance = tolerances_.mouth;
    const geometry::BoundaryHit shore = land_.nearestBoundary(mouth, mouthTolerance);
    if (shore.segment < 0) {
      if (land_.contains(mouth))
        return riverError(i, "ends inland without a lake: its last point " +
                                 lonLatText(lonLat.back()) + " is more than " +
                                 kmText(mouthTolerance) +
                                 " from the coast and every lake shore (a river ends on a shore)");
      return riverError(i, "its last point " + lonLatText(lonLat.back()) + " is more than " +
                               kmText(mouthTolerance) +
                               " out in the water; end it on the coast or a lake shore");
    }
    // Every sample farther than the mouth tolerance from the mouth must lie within half the
    // off-land tolerance of the land; samples 1/2 of it apart then keep every point of the
    // line within the tolerance. Segments that stay farther than that from the shore all lie
    // on the side of their first point, so only those near the shore are sampled.
    const double half = 0.5 * tolerances_.offLand;
    if (!nearLand(line.front(), half))
      return riverError(i,
                        "its source (point 0) " + lonLatText(lonLat.front()) + " is off the land");
    for (std::size_t k = 0; k + 1 < line.size(); ++k) {
      const Vec2 a = line[k];
      const Vec2 b = line[k + 1];
      if (!land_.segmentNearBoundary(a, b, tolerances_.offLand))
        continue;
      const double length = geometry::length(b - a);
      const auto steps = static_cast<std::size_t>(std::ceil(length / half));
      for (std::size_t s = 1; s <= steps; ++s) {
        const Vec2 p = a + (b - a) * (static_cast<double>(s) / static_cast<double>(steps));
        if (geometry::distance(p, mouth) <= mouthTolerance || nearLand(p, half))
          continue;
        return riverError(i, "leaves the land at " + lonLatText(projection_.inverse(p)) +
                                 " (between points " + std::to_string(k) + " and " +
                                 std::to_string(k + 1) + ", away from its mouth)");
      }
    }
    // The points beyond the mouth zone too: an unsampled segment that starts off the land in the
    // zone (not checked) and leaves it has such a point at its far end.
    for (std::size_t k = 1; k + 1 < line.size(); ++k)
      if (geometry::distance(line[k], mouth) > mouthTolerance && !nearLand(line[k], half))
        return riverError(i, "leaves the land at point " + std::to_string(k) + " " +
                                 lonLatText(lonLat[k]));
    return base::Ok{};
  }

  struct Segment {
    Vec2 a;
    Vec2 b;
    bool river = false;
    std::size_t feature = 0; ///< Index in Features::rivers or ::ridges.
    std::size_t k = 0;       ///< Segment k joins points k and k + 1.
  };

  std::string label(const Segment& s) const {
    return s.river ? labels_.rivers[s.feature] : labels_.ridges[s.feature];
  }

  /// A point where [a, b] and [c, d], which intersect, meet.
  static Vec2 meetingPoint(Vec2 a, Vec2 b, Vec2 c, Vec2 d) noexcept {
    const double denominator = geometry::cross(b - a, d - c);
    if (denominator != 0.0) {
      const double t = std::clamp(geometry::cross(c - a, d - c) / denominator, 0.0, 1.0);
      return a + (b - a) * t;
    }
    for (const Vec2 p : {c, d})
      if (geometry::pointSegmentDistance(p, a, b) == 0.0)
        return p;
    return geometry::pointSegmentDistance(a, c, d) == 0.0 ? a : b;
  }

  /// Adjacent segments of one line meet at their shared point; they (nearly) overlap when the
  /// line turns back by more than 179° (straight lines of lon/lat bend a little in the frame).
  static bool foldsBack(const Segment& s, const Segment& t) noexcept {
    const Vec2 u = s.b - s.a;
    const Vec2 v = t.b - t.a;
    const double cosOneDegree = 0.99984769515639124;
    return geometry::dot(u, v) < -cosOneDegree * geometry::length(u) * geometry::length(v);
  }

  base::Status checkCrossings() const {
    std::vector<Segment> segments;
    geometry::Aabb box;
    auto add = [&](const std::vector<Vec2>& line, bool river, std::size_t feature) {
      for (std::size_t k = 0; k + 1 < line.size(); ++k) {
        segments.push_back(Segment{line[k], line[k + 1], river, feature, k});
        box.add(line[k]);
        box.add(line[k + 1]);
      }
    };
    for (std::size_t i = 0; i < features_.rivers.size(); ++i)
      add(features_.rivers[i].line, true, i);
    for (std::size_t i = 0; i < features_.ridges.size(); ++i)
      add(features_.ridges[i].line, false, i);
    if (features_.rivers.empty() || segments.empty())
      return base::Ok{};
    double total = 0.0;
    for (const Segment& s : segments)
      total += geometry::length(s.b - s.a);
    const double cell = std::max(total / static_cast<double>(segments.size()), 1.0);
    geometry::GridIndex grid(box, cell);
    const auto boxOf = [&](std::uint32_t id) {
      geometry::Aabb b;
      b.add(segments[id].a);
      b.add(segments[id].b);
      return b;
    };
    grid.insertAll(static_cast<std::uint32_t>(segments.size()), boxOf);
    std::vector<std::uint32_t> near;
    for (std::uint32_t i = 0; i < segments.size(); ++i) {
      const Segment& s = segments[i];
      if (!s.river)
        continue; // ridges may meet ridges
      near.clear();
      grid.query(boxOf(i), [&](std::uint32_t j) {
        if (j > i)
          near.push_back(j);
        return true;
      });
      std::sort(near.begin(), near.end());
      near.erase(std::unique(near.begin(), near.end()), near.end());
      for (const std::uint32_t j : near) {
        const Segment& t = segments[j];
        const bool same = t.river && t.feature == s.feature;
        if (same && t.k == s.k + 1) {
          if (foldsBack(s, t))
            return riverError(s.feature, "doubles back on itself at point " + std::to_string(t.k) +
                                             " " + lonLatText(projection_.inverse(t.a)));
          continue;
        }
        if (!geometry::segmentsIntersect(s.a, s.b, t.a, t.b))
          continue;
        const std::string at = lonLatText(projection_.inverse(meetingPoint(s.a, s.b, t.a, t.b)));
        if (same)
          return riverError(s.feature, "crosses itself at " + at + " (segments " +
                                           std::to_string(s.k) + " and " + std::to_string(t.k) +
                                           ")");
        return riverError(
            s.feature,
            "crosses " + label(t) + " at " + at + " (its segment " + std::to_string(s.k) + ")" +
                (t.river ? "; drawn rivers may not meet" : "; no river crosses a drawn ridge"));
      }
    }
    return base::Ok{};
  }

  base::Status checkMouthSpacing() const {
    const std::size_t n = features_.rivers.size();
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), std::size_t{0});
    const auto mouth = [&](std::size_t i) { return features_.rivers[i].line.back(); };
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return mouth(a).x < mouth(b).x; });
    const double spacing = params_.mouthSpacing;
    std::size_t worstA = n;
    std::size_t worstB = n;
    for (std::size_t p = 0; p < n; ++p)
      for (std::size_t q = p + 1; q < n && mouth(order[q]).x - mouth(order[p]).x < spacing; ++q) {
        const std::size_t a = std::min(order[p], order[q]);
        const std::size_t b = std::max(order[p], order[q]);
        if (geometry::distance(mouth(a), mouth(b)) < spacing &&
            (worstA == n || std::pair(a, b) < std::pair(worstA, worstB))) {
          worstA = a;
          worstB = b;
        }
      }
    if (worstA == n)
      return base::Ok{};
    return riverError(worstB,
                      "its mouth " + lonLatText(features_.rivers[worstB].lonLat.back()) + " is " +
                          kmText(geometry::distance(mouth(worstA), mouth(worstB))) +
                          " from the mouth of " + labels_.rivers[worstA] + " at " +
                          lonLatText(features_.rivers[worstA].lonLat.back()) +
                          "; mouths must be at least mouthSpacing = " + kmText(spacing) + " apart");
  }

  const Features& features_;
  const FeatureLabels& labels_;
  const geometry::LocalProjection& projection_;
  geometry::PolygonIndex land_;
  const Params& params_;
  FeatureTolerances tolerances_;
};

} // namespace

std::string lonLatText(Vec2 lonLat) {
  std::array<char, 64> buffer{};
  std::snprintf(buffer.data(), buffer.size(), "(%.5f, %.5f)", lonLat.x, lonLat.y);
  return buffer.data();
}

base::Status checkFeatures(const Features& features, const FeatureLabels& labels,
                           const geometry::LocalProjection& projection,
                           const geometry::MultiPolygon& landLocal, const Params& params) {
  if (features.empty())
    return base::Ok{};
  return FeatureChecker(features, labels, projection, landLocal, params).run();
}

} // namespace strahler::input::detail
