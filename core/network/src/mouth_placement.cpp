#include "strahler/network/mouth_placement.h"

#include "barriers.h"
#include "edge_rules.h"

#include "strahler/geometry/distance.h"
#include "strahler/network/drawn_rivers.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace strahler::network {
namespace {

using geometry::Vec2;

constexpr double kUserMouthMaxDistance = 5000.0; // metres from the shore
/// Half-angle of the cone inland of a mouth in which a drawn mountain makes it face the range.
constexpr double kFacingHalfAngle = std::numbers::pi / 6.0;

/// Arc-length parametrisation of a closed ring.
class RingWalker {
public:
  explicit RingWalker(const geometry::Ring& ring) : ring_(ring) {
    cumulative_.reserve(ring.size() + 1);
    cumulative_.push_back(0.0);
    for (std::size_t i = 0; i < ring.size(); ++i)
      cumulative_.push_back(cumulative_.back() + distance(ring[i], ring[(i + 1) % ring.size()]));
  }
  double length() const noexcept { return cumulative_.back(); }
  Vec2 at(double s) const noexcept {
    const double total = length();
    s = std::fmod(s, total);
    if (s < 0)
      s += total;
    const auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), s);
    const auto i =
        static_cast<std::size_t>(std::max<std::ptrdiff_t>(0, it - cumulative_.begin() - 1));
    const double segment = cumulative_[i + 1] - cumulative_[i];
    const double t = segment > 0 ? (s - cumulative_[i]) / segment : 0.0;
    return lerp(ring_[i], ring_[(i + 1) % ring_.size()], t);
  }

private:
  const geometry::Ring& ring_;
  std::vector<double> cumulative_;
};

struct Candidate {
  MouthSite site;
  std::uint32_t ring = 0;
  std::uint32_t order = 0; // sampling order, the final tie-breaker
};

double accessibility(const geometry::PolygonIndex& land, Vec2 p, double radius) {
  constexpr int kDirections = 16;
  double inside = 0.0, total = 0.0;
  for (int ring = 1; ring <= 3; ++ring) {
    const double r = radius * ring / 3.0;
    for (int k = 0; k < kDirections; ++k) {
      const double angle = 2.0 * std::numbers::pi * (k + 0.5 * (ring % 2)) / kDirections;
      if (land.contains(p + geometry::direction(angle) * r))
        inside += r;
      total += r;
    }
  }
  return inside / total;
}

/// Γ sampled every e/2, where a first edge straight inland would be valid; each sample scored
/// by its accessibility when `score` is set.
std::vector<Candidate> sampleShore(const input::Params& params, const geometry::PolygonIndex& land,
                                   bool score) {
  std::vector<Candidate> candidates;
  const double step = params.edgeLength * 0.5;
  for (std::uint32_t r = 0; r < land.rings().size(); ++r) {
    const RingWalker walker(*land.rings()[r]);
    const auto count = static_cast<std::size_t>(std::floor(walker.length() / step));
    for (std::size_t i = 0; i < count; ++i) {
      const double s = static_cast<double>(i) * step;
      const Vec2 p = walker.at(s);
      const Vec2 tangent = walker.at(s + params.edgeLength) - walker.at(s - params.edgeLength);
      if (lengthSquared(tangent) == 0.0)
        continue;
      const Vec2 inward = normalize(perpendicular(tangent));
      if (!detail::mouthEdgeValid(land, p, p + inward * params.edgeLength, params.delta))
        continue;
      Candidate c;
      c.site.position = p;
      c.site.inward = inward;
      c.site.onLake = land.isHole(r);
      c.site.accessibility = score ? accessibility(land, p, params.accessibilityRadius) : 0.0;
      c.ring = r;
      c.order = static_cast<std::uint32_t>(candidates.size());
      candidates.push_back(c);
    }
  }
  return candidates;
}

bool farFromAll(const std::vector<MouthSite>& chosen, const geometry::GridIndex& grid, Vec2 p,
                double spacing) {
  geometry::Aabb box;
  box.add(p);
  return grid.query(box.expanded(spacing),
                    [&](std::uint32_t i) { return distance(chosen[i].position, p) >= spacing; });
}

/// Whether a drawn mountain lies within kFacingHalfAngle of the mouth's inward normal.
bool facesMountain(const MouthSite& m, const std::vector<input::MountainFeature>& mountains) {
  const double cosHalf = std::cos(kFacingHalfAngle);
  return std::any_of(mountains.begin(), mountains.end(), [&](const input::MountainFeature& f) {
    const Vec2 to = f.position - m.position;
    return lengthSquared(to) > 0.0 && dot(normalize(to), m.inward) >= cosHalf;
  });
}

void assignPriorities(std::vector<MouthSite>& mouths, int maxPriority,
                      const std::vector<input::MountainFeature>& mountains) {
  std::vector<std::size_t> seaOrder;
  for (std::size_t i = 0; i < mouths.size(); ++i) {
    if (mouths[i].onLake)
      mouths[i].priority = 1;
    else
      seaOrder.push_back(i);
  }
  // Mouths whose catchment faces a drawn mountain rank first (none without mountains).
  std::vector<bool> facing(mouths.size(), false);
  for (std::size_t i : seaOrder)
    facing[i] = !mountains.empty() && facesMountain(mouths[i], mountains);
  std::stable_sort(seaOrder.begin(), seaOrder.end(), [&](std::size_t a, std::size_t b) {
    if (facing[a] != facing[b])
      return bool(facing[a]);
    return mouths[a].accessibility > mouths[b].accessibility;
  });
  for (std::size_t rank = 0; rank < seaOrder.size(); ++rank) {
    const int level = static_cast<int>(std::floor(std::log2(static_cast<double>(rank) + 1.0)));
    mouths[seaOrder[rank]].priority = std::max(1, maxPriority - level);
  }
}

std::vector<MouthSite> placeAutomatic(const input::Params& params,
                                      const geometry::PolygonIndex& land,
                                      const std::vector<input::MountainFeature>& mountains) {
  std::vector<Candidate> candidates = sampleShore(params, land, true);
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const Candidate& a, const Candidate& b) {
                     return a.site.accessibility > b.site.accessibility;
                   });
  std::vector<MouthSite> chosen;
  std::vector<bool> ringHasMouth(land.rings().size(), false);
  geometry::GridIndex grid(land.bounds().expanded(params.mouthSpacing), params.mouthSpacing);
  auto take = [&](const Candidate& c) {
    geometry::Aabb box;
    box.add(c.site.position);
    grid.insert(box, static_cast<std::uint32_t>(chosen.size()));
    chosen.push_back(c.site);
    ringHasMouth[c.ring] = true;
  };
  for (const Candidate& c : candidates)
    if (farFromAll(chosen, grid, c.site.position, params.mouthSpacing))
      take(c);
  // Every island (outer ring) that can hold a river gets at least its best mouth.
  for (const Candidate& c : candidates)
    if (!ringHasMouth[c.ring] && !land.isHole(c.ring) &&
        farFromAll(chosen, grid, c.site.position, params.sigma))
      take(c);
  assignPriorities(chosen, params.maxPriority, mountains);
  return chosen;
}

base::Result<std::vector<MouthSite>> snapUserMouths(const input::WorldSpec& spec,
                                                    const geometry::PolygonIndex& land) {
  std::vector<MouthSite> sites;
  for (std::size_t i = 0; i < spec.mouths.size(); ++i) {
    const input::UserMouth& m = spec.mouths[i];
    const geometry::BoundaryHit hit = land.nearestBoundary(m.position, kUserMouthMaxDistance);
    if (hit.segment < 0)
      return base::makeError(base::ErrorCode::kInvalidInput,
                             "mouth " + std::to_string(i) + " at (" + std::to_string(m.lonLat.x) +
                                 ", " + std::to_string(m.lonLat.y) +
                                 ") is more than 5 km from any shore");
    const geometry::BoundarySegment& seg = land.segments()[static_cast<std::size_t>(hit.segment)];
    MouthSite site;
    site.position = hit.point;
    site.inward = normalize(perpendicular(seg.b - seg.a));
    site.priority = m.priority;
    site.onLake = land.isHole(seg.ring);
    site.accessibility = accessibility(land, hit.point, spec.params.accessibilityRadius);
    sites.push_back(site);
  }
  return sites;
}

/// The drawn rivers' mouths first (priority maxPriority), then the mouths of `placed` that lie
/// at least mouthSpacing from every drawn mouth and more than σ from every drawn river.
base::Result<std::vector<MouthSite>> withDrawnMouths(const input::WorldSpec& spec,
                                                     const geometry::PolygonIndex& land,
                                                     std::vector<MouthSite> placed) {
  std::vector<std::optional<DrawnCourse>> courses;
  std::vector<MouthSite> sites;
  for (std::size_t i = 0; i < spec.features.rivers.size(); ++i) {
    courses.push_back(drawnCourse(spec.features.rivers[i], land, spec.params));
    if (!courses.back())
      return base::makeError(base::ErrorCode::kInvalidInput,
                             "river " + std::to_string(i) + " ends more than 5 km from any shore");
    MouthSite site;
    site.position = courses.back()->line.back();
    site.inward = courses.back()->inward;
    site.priority = spec.params.maxPriority;
    site.onLake = courses.back()->onLake;
    site.drawnRiver = static_cast<int>(i);
    sites.push_back(site);
  }
  const detail::Barriers barriers(spec, land, courses);
  const std::size_t drawn = sites.size();
  for (const MouthSite& m : placed) {
    const bool nearDrawn =
        std::any_of(sites.begin(), sites.begin() + std::ptrdiff_t(drawn), [&](const MouthSite& d) {
          return distance(d.position, m.position) < spec.params.mouthSpacing;
        });
    if (!nearDrawn && barriers.farFromRivers(m.position))
      sites.push_back(m);
  }
  return sites;
}

} // namespace

std::vector<MouthSite> shoreSites(const input::Params& params, const geometry::PolygonIndex& land) {
  std::vector<MouthSite> sites;
  for (const Candidate& c : sampleShore(params, land, false))
    sites.push_back(c.site);
  return sites;
}

base::Result<std::vector<MouthSite>> placeMouths(const input::WorldSpec& spec,
                                                 const geometry::PolygonIndex& land) {
  if (!spec.mouths.empty()) {
    STRAHLER_ASSIGN_OR_RETURN(std::vector<MouthSite> user, snapUserMouths(spec, land));
    if (spec.features.rivers.empty())
      return user;
    return withDrawnMouths(spec, land, std::move(user));
  }
  std::vector<MouthSite> mouths = placeAutomatic(spec.params, land, spec.features.mountains);
  if (!spec.features.rivers.empty())
    return withDrawnMouths(spec, land, std::move(mouths));
  if (mouths.empty())
    return base::makeError(base::ErrorCode::kInvalidInput,
                           "no river mouth fits on this coastline: the land is too small or "
                           "too narrow for edgeLength and delta (try smaller values)");
  return mouths;
}

} // namespace strahler::network
