#include "strahler/construction/world.h"

#include "evaluation_lanes.h"
#include "folds.h"
#include "relief_field.h"
#include "tributaries.h"

#include "strahler/base/random.h"
#include "strahler/geometry/distance.h"
#include "strahler/primitives/river_primitives.h"
#include "strahler/simd/lanes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace strahler::construction {
namespace {

using geometry::Vec2;

constexpr double kGridCell = 500.0; // m
constexpr std::uint64_t kNoiseStream = 0x746572726e6full;
constexpr std::uint64_t kGullyStream = 0x67756c6c79ull;
constexpr std::uint64_t kTributaryStream = 0x7472696275746172ull;
constexpr double kShelfReach = CoastShape::kShelfReach;

/// A radius with a margin far above the rounding of distances between coordinates: points
/// farther than it are beyond the radius in computed distances too.
double withRoundingMargin(double radius) noexcept {
  return radius * (1.0 + 1e-9) + 1e-6;
}

geometry::Aabb worldBounds(const WorldData& data) {
  geometry::Aabb box = geometry::bounds(data.land);
  for (const primitives::TerrainPrimitive& t : data.terrain)
    box.add(geometry::Aabb{t.center, t.center}.expanded(t.radius));
  for (const primitives::RiverPrimitive& r : data.rivers)
    box.add(primitives::supportBox(r));
  if (box.empty())
    box.add(Vec2{0, 0});
  return box;
}

/// The octaves that survive the LOD fade at `spacing` (they get shorter, so a prefix) and
/// their fades. Each costs a division, and callers sweep rows of equal spacing (or pairs of
/// rows), so the last two are kept per thread (a pure function of the spacing: same values).
const detail::OctaveFades& fadesAt(double spacing) noexcept {
  thread_local std::array<detail::OctaveFades, 2> kept{
      {{std::numeric_limits<double>::quiet_NaN(), 0, {}},
       {std::numeric_limits<double>::quiet_NaN(), 0, {}}}};
  thread_local std::size_t older = 0;
  for (const detail::OctaveFades& f : kept)
    if (f.spacing == spacing)
      return f;
  detail::OctaveFades& fades = kept[older];
  older ^= 1;
  int active = 0;
  for (double wavelength = NoiseOctaves::kLongest;
       active < NoiseOctaves::kOctaves && octaveFade(wavelength, spacing) > 0.0;
       wavelength *= 0.5) {
    fades.fade[static_cast<std::size_t>(active)] = octaveFade(wavelength, spacing);
    ++active;
  }
  fades.active = active;
  fades.spacing = spacing;
  return fades;
}

} // namespace

namespace detail {
/// The world as the tributary network reads it.
class WorldTributarySource final : public TributarySource {
public:
  explicit WorldTributarySource(const World& world) : world_(world) {}
  double controlHeight(Vec2 p) const override { return world_.controlHeight(p); }
  bool onLand(Vec2 p) const override { return world_.land_.contains(p); }
  double groundHeight(Vec2 p, double spacing) const override {
    return world_.uncarvedHeight(p, spacing);
  }
  bool nearestRiver(Vec2 p, double reach, Vec2 downhill, ChannelPoint& out) const override {
    const World& w = world_;
    const double cell = w.riverGrid_.cellSize();
    std::vector<std::uint32_t>& seen = scratch();
    seen.clear();
    for (double y = p.y - reach; y < p.y + reach + cell; y += cell)
      for (double x = p.x - reach; x < p.x + reach + cell; x += cell) {
        const Vec2 q{std::min(x, p.x + reach), std::min(y, p.y + reach)};
        for (const World::RiverCandidate& c : w.riverCells_[w.riverGrid_.cellIndexAt(q)])
          seen.push_back(c.id);
      }
    std::sort(seen.begin(), seen.end());
    seen.erase(std::unique(seen.begin(), seen.end()), seen.end());
    const double reach2 = reach * reach;
    double best = std::numeric_limits<double>::max();
    bool found = false;
    for (const std::uint32_t id : seen) {
      const World::HotRiver& hot = w.hotRivers_[id];
      for (std::uint32_t k = 0; k < hot.segmentCount; ++k) {
        const World::HotSegment& g = w.hotSegments_[hot.segmentBegin + k];
        const Vec2 from = p - g.a;
        const double t =
            std::clamp((from.x * g.ab.x + from.y * g.ab.y) * g.inverseLength2, 0.0, 1.0);
        const Vec2 e = from - g.ab * t;
        const double d2 = e.x * e.x + e.y * e.y;
        if (d2 >= reach2)
          continue;
        const Vec2 q = g.a + g.ab * t;
        const double cost = detail::linkCost(p, q, downhill);
        if (cost < best) {
          best = cost;
          found = true;
          const std::size_t at = 2 * std::size_t{hot.segmentBegin + k};
          out.position = q;
          out.downstream = geometry::normalize(g.ab);
          out.elevation = w.water_[at] + w.water_[at + 1] * t;
          out.fall = std::max(0.0, -w.water_[at + 1]) * std::sqrt(g.inverseLength2);
          out.distance = std::sqrt(d2);
        }
      }
    }
    return found;
  }

private:
  static std::vector<std::uint32_t>& scratch() {
    thread_local std::vector<std::uint32_t> ids;
    return ids;
  }
  const World& world_;
};
} // namespace detail

double octaveFade(double wavelength, double spacing) noexcept {
  if (spacing <= 0.0)
    return 1.0;
  return std::clamp(wavelength / spacing * 0.5 - 1.0, 0.0, 1.0);
}

World::World(WorldData data)
    : data_(std::move(data)), land_(data_.land), terrainGrid_(worldBounds(data_), kGridCell),
      riverGrid_(worldBounds(data_), kGridCell), noise_(data_.params.seed ^ kNoiseStream),
      gullySeed_(static_cast<std::uint32_t>(base::mixHash(data_.params.seed, kGullyStream))),
      tributaries_(data_.params.tributaryLevels > 0
                       ? std::make_shared<detail::Tributaries>(
                             base::mixHash(data_.params.seed, kTributaryStream),
                             data_.params.tributaryLevels)
                       : nullptr),
      folds_(data_.features.mountains.empty()
                 ? nullptr
                 : std::make_shared<detail::Folds>(data_, land_, worldBounds(data_))),
      relief_(data_.relief.empty() ? nullptr
                                   : std::make_shared<detail::ReliefField>(data_.relief)) {
  hot_.reserve(data_.terrain.size());
  for (const primitives::TerrainPrimitive& t : data_.terrain) {
    const double radius2 = t.radius * t.radius;
    hot_.push_back({t.center, radius2, radius2 > 0.0 ? 1.0 / radius2 : 0.0, t.elevation, t.slope,
                    std::max(t.amplitude, 0.0), std::clamp(t.roughness, 0.0, kMaxRoughness)});
    terrainReach_ = std::max(terrainReach_, withRoundingMargin(t.radius));
  }
  terrainGrid_.insertAll(static_cast<std::uint32_t>(data_.terrain.size()), [&](std::uint32_t i) {
    const primitives::TerrainPrimitive& t = data_.terrain[i];
    return geometry::Aabb{t.center, t.center}.expanded(t.radius);
  });
  std::size_t segments = 0, runs = 0;
  for (const primitives::RiverPrimitive& river : data_.rivers) {
    const std::size_t n = river.curve.size() > 0 ? river.curve.size() - 1 : 0;
    segments += n;
    runs += (n + detail::kChunk - 1) / detail::kChunk;
  }
  hotRivers_.reserve(data_.rivers.size());
  hotSegments_.reserve(segments);
  water_.reserve(2 * segments);
  chunkBoxes_.reserve(runs);
  for (std::uint32_t i = 0; i < data_.rivers.size(); ++i) {
    const primitives::RiverPrimitive& river = data_.rivers[i];
    const std::vector<primitives::CurvePoint>& curve = river.curve;
    HotRiver& hot = hotRivers_.emplace_back();
    hot.support = primitives::supportBox(river);
    hot.radius = river.radius;
    hot.minReach = std::min(primitives::valleyMinReach(river.type, river.widthUp, river.widthDown),
                            river.radius);
    hot.reach = withRoundingMargin(river.radius);
    hot.widthUp = river.widthUp;
    hot.widthDown = river.widthDown;
    hot.depthUp = river.depthUp;
    hot.depthDown = river.depthDown;
    hot.bankSlope = primitives::bankSlope(river.type);
    hot.flatBed = primitives::hasFlatBed(river.type);
    hot.chunkBegin = static_cast<std::uint32_t>(chunkBoxes_.size());
    for (std::size_t k = 0; k + 1 < curve.size(); k += detail::kChunk) {
      geometry::Aabb box;
      for (std::size_t j = k; j <= std::min(k + detail::kChunk, curve.size() - 1); ++j)
        box.add(curve[j].position);
      chunkBoxes_.push_back(box);
    }
    hot.chunkCount = static_cast<std::uint32_t>(chunkBoxes_.size()) - hot.chunkBegin;
    hot.segmentBegin = static_cast<std::uint32_t>(hotSegments_.size());
    for (std::size_t k = 0; k + 1 < curve.size(); ++k) {
      const Vec2 a = curve[k].position, ab = curve[k + 1].position - a;
      const double length2 = lengthSquared(ab);
      hotSegments_.push_back({a, ab, length2 > 0.0 ? 1.0 / length2 : 0.0});
      water_.push_back(curve[k].elevation);
      water_.push_back(curve[k + 1].elevation - curve[k].elevation);
    }
    hot.segmentCount = static_cast<std::uint32_t>(hotSegments_.size()) - hot.segmentBegin;
  }
  riverGrid_.insertAll(static_cast<std::uint32_t>(hotRivers_.size()),
                       [&](std::uint32_t i) { return hotRivers_[i].support; });
  riverCells_.resize(riverGrid_.cellCount());
  for (std::size_t c = 0; c < riverGrid_.cellCount(); ++c) {
    // Points land in a cell by a rounded division: a little slack around its box.
    const geometry::Aabb box = riverGrid_.cellBox(c).expanded(1e-6 * riverGrid_.cellSize());
    for (const std::uint32_t i : riverGrid_.cell(c)) {
      const std::span<const geometry::Aabb> chunks = riverChunks(base::PrimitiveId(i));
      const geometry::Aabb near = box.expanded(riverReach(base::PrimitiveId(i)));
      RiverCandidate candidate{i, 0, 0};
      for (std::uint32_t k = 0; k < chunks.size(); ++k)
        if (chunks[k].intersects(near)) {
          if (candidate.endChunk == 0)
            candidate.firstChunk = k;
          candidate.endChunk = k + 1;
        }
      if (candidate.endChunk > 0) // otherwise no point of the cell is within the radius
        riverCells_[c].push_back(candidate);
    }
  }
}

const TectonicPlates* World::plates() const noexcept {
  return folds_ ? &folds_->plates() : nullptr;
}

double World::foldStrength(Vec2 p) const noexcept {
  return folds_ ? folds_->strength(p) : 0.0;
}

double World::controlHeight(Vec2 p) const noexcept {
  double weight = 0.0, height = 0.0;
  for (const std::uint32_t i : terrainGrid_.cellAt(p)) {
    const HotTerrain& t = hot_[i];
    const Vec2 d = p - t.center;
    const double d2 = d.x * d.x + d.y * d.y;
    if (d2 >= t.radius2)
      continue;
    const double u = 1.0 - d2 * t.inverseRadius2;
    weight += u * u;
    height += u * u * (t.elevation + t.slope.x * d.x + t.slope.y * d.y);
  }
  return weight > 0.0 ? height / weight : 0.0;
}

double World::uncarvedHeight(Vec2 p, double spacing) const noexcept {
  double h = 0.0, w = 0.0;
  Sample river;
  terrainLanes(1, &p, nullptr, {spacing, spacing}, terrainGrid_.cellAt(p), &h, &w);
  riversLanes(1, &p, spacing, &h, riverCells_[riverGrid_.cellIndexAt(p)], &river.h, &river.w);
  double height = shapeCoast(p, {h, w}, river, Coast::kUnknown);
  addRelief(&p, spacing, &river.w, {&height, 1});
  return height;
}

double World::carveTributaries(Vec2 p, double h, double spacing) const {
  if (!tributaries_ || !(h > 0.0))
    return h;
  return tributaries_->carve(detail::WorldTributarySource(*this), p, h, spacing);
}

void World::carveGroup(const Vec2* group, double spacing, std::span<double> heights) const {
  if (!tributaries_) // the default: one test per group, no call per sample
    return;
  for (std::size_t l = 0; l < heights.size(); ++l)
    heights[l] = carveTributaries(group[l], heights[l], spacing);
}

double World::riverReach(base::PrimitiveId i) const noexcept {
  return hotRivers_[i.index()].reach;
}

void World::terrainLanes(std::size_t lanes, const Vec2* first, const Vec2* second,
                         std::array<double, 2> spacing, std::span<const std::uint32_t> ids,
                         double* h, double* w) const noexcept {
  const detail::OctaveFades& firstFades = fadesAt(spacing[0]);
  const detail::OctaveFades& secondFades = second ? fadesAt(spacing[1]) : firstFades;
  detail::TerrainSums sums;
  const detail::TerrainLaneArgs args{hot_.data(),
                                     ids,
                                     {&firstFades, &secondFades},
                                     &noise_,
                                     gullySeed_,
                                     !relief_,
                                     {first, second},
                                     second ? 2u : 1u,
                                     h,
                                     w,
                                     &sums,
                                     folds_.get()};
  if (lanes == 1)
    detail::terrainPoint(args);
  else
    detail::terrainLanes(args);
}

void World::riversLanes(std::size_t lanes, const Vec2* points, double spacing,
                        const double* terrain, std::span<const RiverCandidate> rivers,
                        double* riverH, double* riverW) const noexcept {
  if (rivers.empty()) { // most runs: no call
    std::fill_n(riverH, lanes, 0.0);
    std::fill_n(riverW, lanes, 0.0);
    return;
  }
  const detail::RiverLaneArgs args{rivers,
                                   hotRivers_.data(),
                                   chunkBoxes_.data(),
                                   hotSegments_.data(),
                                   water_.data(),
                                   points,
                                   spacing,
                                   terrain,
                                   riverH,
                                   riverW};
  if (lanes == 1)
    detail::riversPoint(args);
  else
    detail::riversLanes(args);
}

void World::addRelief(const Vec2* group, double spacing, const double* riverW,
                      std::span<double> heights) const noexcept {
  if (!relief_)
    return;
  for (std::size_t l = 0; l < heights.size(); ++l)
    if (riverW[l] < 1.0) // a river's floor keeps its line and depth
      heights[l] += relief_->at(group[l], spacing);
}

void World::insideLand(const Vec2* group, double* onLand) const noexcept {
  constexpr auto kLanes = static_cast<std::size_t>(simd::kLanes);
  // A run of a tile's row shares its points' ray band (nearly one y); otherwise, or outside
  // the land's box (whose bands are clamped), point by point.
  const geometry::Aabb& bounds = land_.bounds();
  const auto within = [&](Vec2 p) { return p.y >= bounds.min.y && p.y <= bounds.max.y; };
  const std::optional<geometry::PolygonIndex::RayBand> band =
      within(group[0]) ? std::optional(land_.rayBand(group[0].y)) : std::nullopt;
  const bool shared = band && std::all_of(group, group + kLanes, [&](Vec2 p) {
                        return within(p) && land_.rayBand(p.y).index == band->index;
                      });
  if (!shared) {
    for (std::size_t l = 0; l < kLanes; ++l)
      onLand[l] = land_.contains(group[l]) ? 1.0 : 0.0;
    return;
  }
  detail::insideLanes({land_.segments().data(), band->segments, bounds, group, onLand});
}

double World::shelfReach() noexcept {
  return kShelfReach;
}

double World::shapeCoast(Vec2 p, const Sample& terrain, const Sample& rivers,
                         Coast coast) const noexcept {
  if (coast == Coast::kInland)
    return replace(terrain, rivers).h;
  if (coast == Coast::kFarSea)
    return detail::farSeaPoint(rivers);
  const bool onLand = land_.contains(p);
  return shapeCoast(terrain, rivers, onLand,
                    land_.distanceToBoundary(p, onLand ? CoastShape::kBand : kShelfReach));
}

double World::shapeCoast(const Sample& terrain, const Sample& rivers, bool onLand,
                         double shore) noexcept {
  return detail::coastPoint(terrain, rivers, onLand, shore);
}

World::Evaluation World::evaluate(Vec2 p, double spacing) const noexcept {
  return evaluateFrom(p, spacing, terrainGrid_.cellAt(p), riverCells_[riverGrid_.cellIndexAt(p)]);
}

World::Evaluation World::evaluateFrom(Vec2 p, double spacing,
                                      std::span<const std::uint32_t> terrain,
                                      std::span<const RiverCandidate> rivers,
                                      Coast coast) const noexcept {
  double h = 0.0, w = 0.0;
  Sample river;
  terrainLanes(1, &p, nullptr, {spacing, spacing}, terrain, &h, &w);
  riversLanes(1, &p, spacing, &h, rivers, &river.h, &river.w);
  Evaluation e;
  e.terrain = {h, w};
  e.rivers = river;
  e.tree = replace(e.terrain, e.rivers).h;
  double height = shapeCoast(p, e.terrain, e.rivers, coast);
  addRelief(&p, spacing, &river.w, {&height, 1});
  e.height = carveTributaries(p, height, spacing);
  return e;
}

void World::heights(std::span<const Vec2> points, double spacing,
                    std::span<double> out) const noexcept {
  constexpr auto kLanes = static_cast<std::size_t>(simd::kLanes);
  for (std::size_t begin = 0; begin < points.size(); begin += kLanes) {
    const std::span<const Vec2> group =
        points.subspan(begin, std::min(kLanes, points.size() - begin));
    const std::vector<std::uint32_t>& terrain = terrainGrid_.cellAt(group[0]);
    const std::size_t riverCell = riverGrid_.cellIndexAt(group[0]);
    const std::vector<RiverCandidate>& rivers = riverCells_[riverCell];
    const bool shared = std::all_of(group.begin(), group.end(), [&](Vec2 p) {
      return &terrainGrid_.cellAt(p) == &terrain && riverGrid_.cellIndexAt(p) == riverCell;
    });
    if (shared) {
      heightsFrom(group, spacing, terrain, rivers, {}, out.subspan(begin, group.size()));
      continue;
    }
    for (std::size_t l = 0; l < group.size(); ++l)
      out[begin + l] = height(group[l], spacing);
  }
}

void World::heightsFrom(std::span<const Vec2> points, double spacing,
                        std::span<const std::uint32_t> terrain,
                        std::span<const RiverCandidate> rivers, const Shore& shore,
                        std::span<double> heights) const noexcept {
  constexpr auto kLanes = static_cast<std::size_t>(simd::kLanes);
  std::array<double, kLanes> h, w;
  std::array<Vec2, kLanes> padded;
  for (std::size_t begin = 0; begin < points.size(); begin += kLanes) {
    const std::size_t n = std::min(kLanes, points.size() - begin);
    const Vec2* group = points.data() + begin;
    if (n < kLanes) { // short groups repeat their last point
      for (std::size_t l = 0; l < kLanes; ++l)
        padded[l] = group[std::min(l, n - 1)];
      group = padded.data();
    }
    terrainLanes(kLanes, group, nullptr, {spacing, spacing}, terrain, h.data(), w.data());
    finishGroup(group, spacing, h.data(), w.data(), rivers, shore, heights.subspan(begin, n));
  }
}

void World::heightsFrom(const PointRun& first, const PointRun& second,
                        std::span<const std::uint32_t> terrain, const Shore& shore) const noexcept {
  constexpr auto kLanes = static_cast<std::size_t>(simd::kLanes);
  if (first.points.size() != kLanes || second.points.size() != kLanes) {
    heightsFrom(first.points, first.spacing, terrain, first.rivers, shore, first.heights);
    heightsFrom(second.points, second.spacing, terrain, second.rivers, shore, second.heights);
    return;
  }
  std::array<double, 2 * kLanes> h, w;
  terrainLanes(kLanes, first.points.data(), second.points.data(), {first.spacing, second.spacing},
               terrain, h.data(), w.data());
  finishGroup(first.points.data(), first.spacing, h.data(), w.data(), first.rivers, shore,
              first.heights);
  finishGroup(second.points.data(), second.spacing, h.data() + kLanes, w.data() + kLanes,
              second.rivers, shore, second.heights);
}

void World::finishGroup(const Vec2* group, double spacing, const double* h, const double* w,
                        std::span<const RiverCandidate> rivers, const Shore& shore,
                        std::span<double> heights) const noexcept {
  constexpr auto kLanes = static_cast<std::size_t>(simd::kLanes);
  // Arrays of doubles, not of Samples: GCC zeroes an array of Samples (their members have
  // initialisers) by `rep stos`, which cost more than the river search at most zooms.
  std::array<double, kLanes> riverH, riverW;
  riversLanes(kLanes, group, spacing, h, rivers, riverH.data(), riverW.data());
  const std::size_t n = heights.size();
  if (shore.coast == Coast::kInland) { // shapeCoast()'s inland case, without a call per sample
    for (std::size_t l = 0; l < n; ++l)
      heights[l] = replace({h[l], w[l]}, {riverH[l], riverW[l]}).h;
    addRelief(group, spacing, riverW.data(), heights);
    carveGroup(group, spacing, heights);
    return;
  }
  if (shore.coast != Coast::kUnknown || !shore.segments) { // far at sea, or unknown
    for (std::size_t l = 0; l < n; ++l)
      heights[l] = shapeCoast(group[l], {h[l], w[l]}, {riverH[l], riverW[l]}, shore.coast);
    addRelief(group, spacing, riverW.data(), heights);
    carveGroup(group, spacing, heights);
    return;
  }
  std::array<double, kLanes> onLand, shore2, out;
  // The squared distance to the nearest of the candidate segments, as the land index would
  // find it (the same minimum of the same per-segment values), up to the shelf's reach.
  shore2.fill(kShelfReach * kShelfReach);
  detail::nearestSegmentLanes({land_.segments().data(), *shore.segments, group, shore2.data()});
  if (shore.onLand)
    onLand.fill(*shore.onLand ? 1.0 : 0.0);
  else
    insideLand(group, onLand.data());
  detail::coastLanes(
      {h, w, riverH.data(), riverW.data(), onLand.data(), shore2.data(), out.data()});
  std::copy_n(out.begin(), n, heights.begin());
  addRelief(group, spacing, riverW.data(), heights);
  carveGroup(group, spacing, heights);
}

} // namespace strahler::construction
