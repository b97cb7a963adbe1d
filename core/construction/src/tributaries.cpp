#include "tributaries.h"

#include "strahler/base/random.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <unordered_map>

namespace strahler::construction::detail {
namespace {

using geometry::Vec2;

/// How far (m) a head of each level looks for the channel it joins.
constexpr std::array<double, Tributaries::kLevels> kLinkReach{1100.0, 600.0, 300.0};
/// How far (m) from its channel each level's valley carves.
constexpr std::array<double, Tributaries::kLevels> kSupport{450.0, 250.0, 130.0};
/// A channel's slope at its junction over the mean rise of the ground along it (twice that at
/// its head).
constexpr double kChannelShare = 0.55;
/// Share of the cells of the finer levels left without a channel.
constexpr double kSkipShare = 0.35;
/// How far (m) above the ground a channel's head lies.
constexpr double kHeadroom = 15.0;
/// Most depth (m) of each level's channels below the ground.
constexpr std::array<double, Tributaries::kLevels> kDepth{110.0, 55.0, 16.0};
/// The least rise (m) from a junction to a head for the head to get a channel.
constexpr double kLeastRise = 2.0;
/// Regions kept per thread before the cache is emptied.
constexpr std::size_t kCachedRegions = 256;

std::atomic<std::uint64_t> serials{1};

int haloCells(int level) {
  const double cell = Tributaries::kLevelCell[static_cast<std::size_t>(level)];
  const double far = kLinkReach[static_cast<std::size_t>(level)] +
                     std::max(kSupport[static_cast<std::size_t>(level)], 1.1 * cell);
  return static_cast<int>(std::ceil(far / cell)) + 1;
}

std::int64_t floorDiv(std::int64_t a, std::int64_t b) {
  const std::int64_t q = a / b;
  return (a % b != 0 && (a < 0) != (b < 0)) ? q - 1 : q;
}

/// A uniform number in [0, 1) from a hash.
double unit(std::uint64_t h) {
  return static_cast<double>(h >> 11) * (1.0 / 9007199254740992.0);
}

/// The nearest point of a curve's polyline to p: squared distance, segment and fraction.
struct Nearest {
  double distance2 = 0.0;
  std::size_t segment = 0;
  double along = 0.0;
};
Nearest nearestOnCurve(const Tributaries::Curve& c, Vec2 p, std::size_t first = 0) {
  Nearest best{std::numeric_limits<double>::infinity(), first, 0.0};
  for (std::size_t k = first; k + 1 < c.points.size(); ++k) {
    const Vec2 a = c.points[k], ab = c.points[k + 1] - a;
    const double length2 = ab.x * ab.x + ab.y * ab.y;
    const Vec2 ap = p - a;
    double t = length2 > 0.0 ? (ap.x * ab.x + ap.y * ab.y) / length2 : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    const double ex = ap.x - ab.x * t, ey = ap.y - ab.y * t;
    const double d2 = ex * ex + ey * ey;
    if (d2 < best.distance2)
      best = {d2, k, t};
  }
  return best;
}

double boxGap2(const geometry::Aabb& b, Vec2 p) {
  const double dx = std::max({b.min.x - p.x, 0.0, p.x - b.max.x});
  const double dy = std::max({b.min.y - p.y, 0.0, p.y - b.max.y});
  return dx * dx + dy * dy;
}

struct Key {
  std::uint64_t serial;
  std::int64_t level, rx, ry;
  bool operator==(const Key&) const = default;
};
struct KeyHash {
  std::size_t operator()(const Key& k) const noexcept {
    std::uint64_t h = base::mixHash(k.serial, static_cast<std::uint64_t>(k.level));
    h = base::mixHash(h, static_cast<std::uint64_t>(k.rx));
    return static_cast<std::size_t>(base::mixHash(h, static_cast<std::uint64_t>(k.ry)));
  }
};

struct ThreadCache {
  std::unordered_map<Key, std::shared_ptr<const Tributaries::Region>, KeyHash> regions;
  std::array<Key, Tributaries::kLevels> lastKey{};
  std::array<std::shared_ptr<const Tributaries::Region>, Tributaries::kLevels> last;
};
ThreadCache& threadCache() {
  thread_local ThreadCache cache;
  return cache;
}

} // namespace

double linkCost(Vec2 p, Vec2 q, Vec2 downhill) noexcept {
  const Vec2 to = q - p;
  const double d = length(to);
  if (d <= 0.0)
    return 0.0;
  const double along = (to.x * downhill.x + to.y * downhill.y) / d; // cos of the angle, or 0
  return d * (1.0 + 3.0 * (1.0 - along));
}

Tributaries::Tributaries(std::uint64_t seed, int levels)
    : seed_(seed), levels_(std::clamp(levels, 1, kLevels)), serial_(serials.fetch_add(1)) {}

std::shared_ptr<const Tributaries::Region> Tributaries::region(const TributarySource& world,
                                                               int level, std::int64_t rx,
                                                               std::int64_t ry) const {
  ThreadCache& cache = threadCache();
  const Key key{serial_, level, rx, ry};
  const auto l = static_cast<std::size_t>(level);
  if (cache.last[l] && cache.lastKey[l] == key)
    return cache.last[l];
  auto found = cache.regions.find(key);
  std::shared_ptr<const Region> r;
  if (found != cache.regions.end()) {
    r = found->second;
  } else {
    r = build(world, level, rx, ry);
    if (cache.regions.size() >= kCachedRegions)
      cache.regions.clear(); // holders keep theirs alive
    cache.regions.emplace(key, r);
  }
  cache.lastKey[l] = key;
  cache.last[l] = r;
  return r;
}

bool Tributaries::nearestCoarser(const TributarySource& world, int level, Vec2 p, double reach,
                                 Vec2 downhill, ChannelPoint& out) const {
  bool found = world.nearestRiver(p, reach, downhill, out);
  double best = found ? linkCost(p, out.position, downhill) : std::numeric_limits<double>::max();
  for (int m = 0; m < level; ++m) {
    const double cell = kLevelCell[static_cast<std::size_t>(m)];
    const std::int64_t i = static_cast<std::int64_t>(std::floor(p.x / cell));
    const std::int64_t j = static_cast<std::int64_t>(std::floor(p.y / cell));
    const std::shared_ptr<const Region> r =
        region(world, m, floorDiv(i, kRegionCells), floorDiv(j, kRegionCells));
    const double support = kSupport[static_cast<std::size_t>(m)];
    for (const Curve& c : r->curves) {
      geometry::Aabb raw{c.box.min + Vec2{support, support}, c.box.max - Vec2{support, support}};
      const double gap2 = boxGap2(raw, p);
      if (gap2 >= reach * reach || gap2 >= best * best)
        continue;                                             // the cost is at least the distance
      for (std::size_t k = 1; k + 1 < c.points.size(); ++k) { // not its first sixth (its head)
        const Vec2 a = c.points[k], ab = c.points[k + 1] - a;
        const double length2 = ab.x * ab.x + ab.y * ab.y;
        const Vec2 ap = p - a;
        const double t =
            std::clamp(length2 > 0.0 ? (ap.x * ab.x + ap.y * ab.y) / length2 : 0.0, 0.0, 1.0);
        const Vec2 q = a + ab * t;
        const double d = distance(p, q);
        if (d >= reach)
          continue;
        const double cost = linkCost(p, q, downhill);
        if (cost < best) {
          best = cost;
          found = true;
          out.position = q;
          out.downstream = geometry::normalize(ab);
          out.elevation = c.water[k] + (c.water[k + 1] - c.water[k]) * t;
          out.fall =
              length2 > 0.0 ? std::max(0.0, c.water[k] - c.water[k + 1]) / std::sqrt(length2) : 0.0;
          out.distance = d;
        }
      }
    }
  }
  return found;
}

std::shared_ptr<const Tributaries::Region> Tributaries::build(const TributarySource& world,
                                                              int level, std::int64_t rx,
                                                              std::int64_t ry) const {
  auto region = std::make_shared<Region>();
  const auto l = static_cast<std::size_t>(level);
  const double cell = kLevelCell[l];
  const int halo = haloCells(level);
  const std::int64_t i0 = rx * kRegionCells, j0 = ry * kRegionCells;
  const std::uint64_t levelSeed = base::mixHash(seed_, 0x7472696275ull + l);
  for (std::int64_t j = j0 - halo; j < j0 + kRegionCells + halo; ++j)
    for (std::int64_t i = i0 - halo; i < i0 + kRegionCells + halo; ++i) {
      const std::uint64_t h = base::mixHash(base::mixHash(levelSeed, static_cast<std::uint64_t>(i)),
                                            static_cast<std::uint64_t>(j));
      const std::uint64_t h2 = base::mixHash(h, 1), h3 = base::mixHash(h, 2),
                          h4 = base::mixHash(h, 3);
      const Vec2 head{(static_cast<double>(i) + 0.15 + 0.7 * unit(h)) * cell,
                      (static_cast<double>(j) + 0.15 + 0.7 * unit(h2)) * cell};
      // Not every cell of the finer levels holds a channel, and channels differ in depth:
      // gullies of one size at every cell read as a combed pattern.
      const std::uint64_t h5 = base::mixHash(h, 4);
      if (level > 0 && unit(h5) < kSkipShare)
        continue;
      if (!world.onLand(head))
        continue;
      // Downhill on the control height (the primitives' planes), by central differences.
      constexpr double kStep = 10.0;
      const Vec2 gradient{
          world.controlHeight(head + Vec2{kStep, 0}) - world.controlHeight(head - Vec2{kStep, 0}),
          world.controlHeight(head + Vec2{0, kStep}) - world.controlHeight(head - Vec2{0, kStep})};
      const double steepness = length(gradient);
      const Vec2 downhill = steepness > 1e-9 ? gradient * (-1.0 / steepness) : Vec2{};
      ChannelPoint parent;
      if (!nearestCoarser(world, level, head, kLinkReach[l], downhill, parent))
        continue;
      const double length = parent.distance;
      if (length < 0.25 * cell)
        continue; // the head lies on its channel
      const double top = world.controlHeight(head);
      if (top - parent.elevation < kLeastRise + 0.02 * length)
        continue; // no fall towards the channel
      Curve c;
      const Vec2 chord = (parent.position - head) / length;
      const Vec2 end = geometry::normalize(chord + parent.downstream);
      const Vec2 across{-chord.y, chord.x};
      const double wiggle = (unit(h3) - 0.5) * 0.3 * length;
      for (int k = 0; k < kCurvePoints; ++k) {
        const double u = static_cast<double>(k) / (kCurvePoints - 1);
        const double u2 = u * u, u3 = u2 * u;
        const double h00 = 2 * u3 - 3 * u2 + 1, h10 = u3 - 2 * u2 + u, h01 = -2 * u3 + 3 * u2,
                     h11 = u3 - u2;
        Vec2 q = head * h00 + chord * (h10 * length) + parent.position * h01 + end * (h11 * length);
        q += across * (wiggle * std::sin(3.141592653589793 * u));
        c.points[static_cast<std::size_t>(k)] = q;
      }
      c.points[kCurvePoints - 1] = parent.position;
      // The ground along the curve: the control height with the coarser levels' valleys.
      std::array<double, kCurvePoints> ground{};
      for (std::size_t k = 0; k + 1 < kCurvePoints; ++k) {
        const Vec2 q = c.points[k];
        double g = world.groundHeight(q, cell);
        for (int m = 0; m < level; ++m)
          g = carveLevel(world, m, q, g, 0.0);
        ground[k] = g;
      }
      ground[kCurvePoints - 1] = parent.elevation;
      // The water rises from the parent's at the junction, steeper towards the head
      // (concave), never above the ground nor deeper below it than the level's depth (which
      // tapers to nothing at the head: a hollow, not a bowl), and falls all the way
      // (monotone); where the parent lies deeper, the channel drops to it at its mouth.
      const double rise = std::max(0.0, (ground[0] - parent.elevation) / length);
      const double channelSlope = kChannelShare * rise;
      // Valley sides as steep as hillslopes are: a gentle side would carry the channel's
      // level far out under the neighbouring ground (flat-floored discs).
      c.sideSlope = 0.45 + 0.3 * unit(h4);
      // Deep enough to show, shallow enough that its sides reach the ground well within the
      // support (else the fading support leaves a circular step).
      const double depth = std::min(kDepth[l] * (0.4 + 0.9 * unit(base::mixHash(h, 5))),
                                    0.6 * c.sideSlope * kSupport[l]);
      c.water[kCurvePoints - 1] = parent.elevation;
      double fromJunction = 0.0;
      for (std::size_t k = kCurvePoints - 1; k-- > 0;) {
        const double step = distance(c.points[k], c.points[k + 1]);
        fromJunction += step;
        const double u = static_cast<double>(k) / (kCurvePoints - 1); // 0 at the head
        const double taper = std::min(1.0, 2.0 * u);
        const double deepest = ground[k] - depth * taper * (2.0 - taper);
        // Above the ground at the head (the finer relief there must not leave a bowl): the
        // channel emerges from the slope where its water falls below the ground.
        const double upper = ground[k] + kHeadroom * (1.0 - taper);
        const double slope = channelSlope * (1.0 + fromJunction / length);
        const double water =
            k == 0 ? upper : std::max(std::min(c.water[k + 1] + slope * step, upper), deepest);
        // Beside the parent upstream of the junction (where the curve bends to join it), never
        // below the parent's own water there: the channel must not undercut its parent's bed.
        const Vec2 q = c.points[k];
        const double upstream = (parent.position.x - q.x) * parent.downstream.x +
                                (parent.position.y - q.y) * parent.downstream.y;
        const double beside = parent.elevation + parent.fall * std::max(0.0, upstream);
        c.water[k] = std::max({water, beside, c.water[k + 1] + 0.005 * step});
      }
      c.support = kSupport[l];
      geometry::Aabb box;
      for (const Vec2 q : c.points)
        box.add(q);
      c.box = box.expanded(c.support);
      region->curves.push_back(c);
    }
  // Per cell of the region, the curves whose support box meets it.
  constexpr int kCells = kRegionCells * kRegionCells;
  std::vector<std::uint32_t> counts(kCells, 0);
  const auto cellRange = [&](const Curve& c, std::int64_t& a0, std::int64_t& a1, std::int64_t& b0,
                             std::int64_t& b1) {
    a0 = std::max<std::int64_t>(static_cast<std::int64_t>(std::floor(c.box.min.x / cell)) - i0, 0);
    a1 = std::min<std::int64_t>(static_cast<std::int64_t>(std::floor(c.box.max.x / cell)) - i0,
                                kRegionCells - 1);
    b0 = std::max<std::int64_t>(static_cast<std::int64_t>(std::floor(c.box.min.y / cell)) - j0, 0);
    b1 = std::min<std::int64_t>(static_cast<std::int64_t>(std::floor(c.box.max.y / cell)) - j0,
                                kRegionCells - 1);
  };
  for (const Curve& c : region->curves) {
    std::int64_t a0, a1, b0, b1;
    cellRange(c, a0, a1, b0, b1);
    for (std::int64_t b = b0; b <= b1; ++b)
      for (std::int64_t a = a0; a <= a1; ++a)
        ++counts[static_cast<std::size_t>(b * kRegionCells + a)];
  }
  region->cellStart.assign(kCells + 1, 0);
  for (int k = 0; k < kCells; ++k)
    region->cellStart[static_cast<std::size_t>(k) + 1] =
        region->cellStart[static_cast<std::size_t>(k)] + counts[static_cast<std::size_t>(k)];
  region->cellCurves.resize(region->cellStart.back());
  std::vector<std::uint32_t> fill(region->cellStart.begin(), region->cellStart.end() - 1);
  for (std::uint32_t id = 0; id < region->curves.size(); ++id) {
    std::int64_t a0, a1, b0, b1;
    cellRange(region->curves[id], a0, a1, b0, b1);
    for (std::int64_t b = b0; b <= b1; ++b)
      for (std::int64_t a = a0; a <= a1; ++a)
        region->cellCurves[fill[static_cast<std::size_t>(b * kRegionCells + a)]++] = id;
  }
  return region;
}

double Tributaries::carve(const TributarySource& world, Vec2 p, double h, double spacing) const {
  for (int level = 0; level < levels_; ++level)
    h = carveLevel(world, level, p, h, spacing);
  return h;
}

double Tributaries::carveLevel(const TributarySource& world, int level, Vec2 p, double h,
                               double spacing) const {
  {
    const auto l = static_cast<std::size_t>(level);
    const double cell = kLevelCell[l];
    const double fade = spacing <= 0.0 ? 1.0 : std::clamp(cell / spacing * 0.5 - 1.0, 0.0, 1.0);
    if (fade <= 0.0)
      return h;
    const std::int64_t i = static_cast<std::int64_t>(std::floor(p.x / cell));
    const std::int64_t j = static_cast<std::int64_t>(std::floor(p.y / cell));
    const std::int64_t rx = floorDiv(i, kRegionCells), ry = floorDiv(j, kRegionCells);
    const std::shared_ptr<const Region> r = region(world, level, rx, ry);
    const auto at =
        static_cast<std::size_t>((j - ry * kRegionCells) * kRegionCells + (i - rx * kRegionCells));
    // A floor at the water out to just over half a spacing: every row or column of samples
    // that crosses a channel then has a sample on its floor, so the channel drains from
    // sample to sample (as the graph's rivers do with their floors, riverFloor).
    const double floor = 0.55 * spacing;
    constexpr double kRounding = 1.0;
    double deepest = 0.0;
    for (std::uint32_t k = r->cellStart[at]; k < r->cellStart[at + 1]; ++k) {
      const Curve& c = r->curves[r->cellCurves[k]];
      if (p.x < c.box.min.x || p.x > c.box.max.x || p.y < c.box.min.y || p.y > c.box.max.y)
        continue;
      const Nearest n = nearestOnCurve(c, p);
      if (n.distance2 >= c.support * c.support)
        continue;
      const double d = std::sqrt(n.distance2);
      const double water =
          c.water[n.segment] + (c.water[n.segment + 1] - c.water[n.segment]) * n.along;
      const double side = std::max(d - floor, 0.0);
      const double valley =
          water + c.sideSlope * (std::sqrt(side * side + kRounding * kRounding) - kRounding);
      if (valley >= h)
        continue;
      // Whole out to 70 % of the support, fading to nothing at its edge.
      const double t = std::clamp((c.support - d) / (0.3 * c.support), 0.0, 1.0);
      deepest = std::max(deepest, (h - valley) * t * t * (3.0 - 2.0 * t));
    }
    h -= fade * deepest;
  }
  return h;
}

} // namespace strahler::construction::detail
