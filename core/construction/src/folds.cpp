#include "folds.h"

#include "strahler/base/random.h"
#include "strahler/construction/world.h"
#include "strahler/geometry/polygon.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <utility>

namespace strahler::construction::detail {
namespace {

using geometry::Vec2;

constexpr std::uint64_t kFoldStream = 0x666f6c6473ull;
/// The mountains' height the folds scale to when none is drawn with an elevation, m.
constexpr double kDefaultMountainHeight = 2000.0;
/// The cell size at which cells merge while their motions are within 30°; the merge angle
/// scales inversely with the cell size (see mergeThreshold()).
constexpr double kReferenceCell = 40000.0; // m

/// Unit vector of v, or (0, 0) for a null one.
Vec2 unitOrZero(Vec2 v) noexcept {
  const double l = geometry::length(v);
  return l > 0.0 ? v / l : Vec2{0.0, 0.0};
}

/// The dot product of two plates' motions; a plate without motion (its mountains at its
/// centroid: isolated peaks, hot spots) agrees with every other.
double agreement(Vec2 a, Vec2 b) noexcept {
  const Vec2 ua = unitOrZero(a), ub = unitOrZero(b);
  if (geometry::lengthSquared(ua) == 0.0 || geometry::lengthSquared(ub) == 0.0)
    return 1.0;
  return geometry::dot(ua, ub);
}

/// The merge threshold for cells of typical side `cell` m (the square root of the land area
/// per mountain): cos θ with θ = 30° · clamp(kReferenceCell / cell, 0.5, 2), so that dense
/// mountains (small cells) merge into plates more readily than sparse ones.
double mergeThreshold(double cell) noexcept {
  const double ratio = cell > 0.0 ? std::clamp(kReferenceCell / cell, 0.5, 2.0) : 2.0;
  return std::cos(ratio * std::numbers::pi / 6.0);
}

std::uint32_t findRoot(std::vector<std::uint32_t>& parent, std::uint32_t i) {
  while (parent[i] != i) {
    parent[i] = parent[parent[i]];
    i = parent[i];
  }
  return i;
}

} // namespace

Folds::Folds(const WorldData& data, const geometry::PolygonIndex& land,
             const geometry::Aabb& bounds)
    : noise_(base::mixHash(data.params.seed, kFoldStream)) {
  const std::vector<input::MountainFeature>& mountains = data.features.mountains;
  const std::size_t m = mountains.size();
  // The grid: nodes spacing_ apart covering the bounds, at most kMaxNodes of them.
  const Vec2 size = bounds.size();
  spacing_ = std::max(TectonicFolds::kMinNodeSpacing,
                      std::sqrt(std::max(size.x, 1.0) * std::max(size.y, 1.0) /
                                static_cast<double>(TectonicFolds::kMaxNodes)));
  for (;;) {
    nx_ = static_cast<int>(std::ceil(size.x / spacing_)) + 1;
    ny_ = static_cast<int>(std::ceil(size.y / spacing_)) + 1;
    nx_ = std::max(nx_, 2);
    ny_ = std::max(ny_, 2);
    if (static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_) <= TectonicFolds::kMaxNodes)
      break;
    spacing_ *= 1.1;
  }
  inverseSpacing_ = 1.0 / spacing_;
  origin_ = bounds.min;
  const std::size_t nodes = static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_);
  const auto nodeAt = [&](int i, int j) {
    return Vec2{origin_.x + i * spacing_, origin_.y + j * spacing_};
  };

  // Voronoi cells of the mountains over the nodes (ties to the first mountain), and which
  // nodes lie on land.
  std::vector<std::uint32_t> cell(nodes);
  std::vector<std::uint8_t> onLand(nodes);
  std::vector<double> count(m, 0.0);
  std::vector<Vec2> sum(m, Vec2{0.0, 0.0});
  for (int j = 0; j < ny_; ++j)
    for (int i = 0; i < nx_; ++i) {
      const std::size_t n =
          static_cast<std::size_t>(j) * static_cast<std::size_t>(nx_) + static_cast<std::size_t>(i);
      const Vec2 p = nodeAt(i, j);
      std::uint32_t best = 0;
      double best2 = geometry::lengthSquared(p - mountains[0].position);
      for (std::uint32_t k = 1; k < m; ++k) {
        const double d2 = geometry::lengthSquared(p - mountains[k].position);
        if (d2 < best2) {
          best2 = d2;
          best = k;
        }
      }
      cell[n] = best;
      onLand[n] = land.contains(p) ? 1 : 0;
      if (onLand[n]) {
        count[best] += 1.0;
        sum[best] = sum[best] + p;
      }
    }

  // Each cell moves from its land centroid towards its mountain.
  const double nodeArea = spacing_ * spacing_;
  plates_.cellVelocity.resize(m);
  plates_.cellAreaKm2.resize(m);
  for (std::size_t k = 0; k < m; ++k) {
    plates_.cellAreaKm2[k] = count[k] * nodeArea * 1e-6;
    plates_.cellVelocity[k] =
        count[k] > 0.0 ? unitOrZero(mountains[k].position - sum[k] / count[k]) : Vec2{0.0, 0.0};
  }

  // Neighbouring cells: land nodes side by side in different cells (an ordered set).
  std::set<std::pair<std::uint32_t, std::uint32_t>> adjacent;
  for (int j = 0; j < ny_; ++j)
    for (int i = 0; i < nx_; ++i) {
      const std::size_t n =
          static_cast<std::size_t>(j) * static_cast<std::size_t>(nx_) + static_cast<std::size_t>(i);
      if (!onLand[n])
        continue;
      for (const std::size_t o : {i + 1 < nx_ ? n + 1 : n, j + 1 < ny_ ? n + nx_ : n})
        if (o != n && onLand[o] && cell[o] != cell[n])
          adjacent.insert({std::min(cell[n], cell[o]), std::max(cell[n], cell[o])});
    }

  // Merge the neighbouring plates whose motions agree best, one pair at a time, while they
  // agree above the threshold; a plate's motion is the area-weighted sum of its cells'.
  const double landArea = std::max(geometry::area(data.land), 0.0);
  const double typicalCell = std::sqrt(landArea / static_cast<double>(m));
  plates_.mergeThreshold = mergeThreshold(typicalCell);
  plates_.foldReach = std::clamp(0.5 * typicalCell, 5000.0, 50000.0);
  std::vector<std::uint32_t> parent(m);
  std::vector<Vec2> motion(m);
  for (std::uint32_t k = 0; k < m; ++k) {
    parent[k] = k;
    motion[k] = plates_.cellVelocity[k] * count[k];
  }
  for (;;) {
    double best = -2.0;
    std::pair<std::uint32_t, std::uint32_t> pick{0, 0};
    for (const auto& [a, b] : adjacent) {
      const std::uint32_t ra = findRoot(parent, a), rb = findRoot(parent, b);
      if (ra == rb)
        continue;
      const double agree = agreement(motion[ra], motion[rb]);
      if (agree > best) {
        best = agree;
        pick = {std::min(ra, rb), std::max(ra, rb)};
      }
    }
    if (!(best > plates_.mergeThreshold))
      break;
    parent[pick.second] = pick.first;
    motion[pick.first] = motion[pick.first] + motion[pick.second];
  }
  // Plates numbered by their first mountain.
  std::vector<std::uint32_t> number(m, UINT32_MAX);
  plates_.plateOf.resize(m);
  for (std::uint32_t k = 0; k < m; ++k) {
    const std::uint32_t root = findRoot(parent, k);
    if (number[root] == UINT32_MAX) {
      number[root] = static_cast<std::uint32_t>(plates_.velocity.size());
      plates_.velocity.push_back(unitOrZero(motion[root]));
    }
    plates_.plateOf[k] = number[root];
  }
  along_.resize(plates_.velocity.size());
  for (std::size_t p = 0; p < along_.size(); ++p) // a plate without motion folds along x
    along_[p] =
        geometry::lengthSquared(plates_.velocity[p]) > 0.0 ? plates_.velocity[p] : Vec2{1.0, 0.0};

  // Plate boundaries: nodes beside a node of another plate (on land, or beside land). The
  // convergence across a pair is (v_A − v_B) · e / 2 in [−1, 1], e the unit step from A's node
  // to B's (> 0: the plates close in).
  plate_.resize(nodes);
  for (std::size_t n = 0; n < nodes; ++n)
    plate_[n] = plates_.plateOf[cell[n]];
  std::vector<double> convergence(nodes, 0.0);
  std::vector<std::uint8_t> boundary(nodes, 0);
  for (int j = 0; j < ny_; ++j)
    for (int i = 0; i < nx_; ++i) {
      const std::size_t n =
          static_cast<std::size_t>(j) * static_cast<std::size_t>(nx_) + static_cast<std::size_t>(i);
      const std::pair<std::size_t, Vec2> steps[] = {{i + 1 < nx_ ? n + 1 : n, Vec2{1.0, 0.0}},
                                                    {j + 1 < ny_ ? n + nx_ : n, Vec2{0.0, 1.0}}};
      for (const auto& [o, e] : steps) {
        if (o == n || plate_[o] == plate_[n] || !(onLand[n] || onLand[o]))
          continue;
        const double c =
            0.5 * geometry::dot(plates_.velocity[plate_[n]] - plates_.velocity[plate_[o]], e);
        boundary[n] = boundary[o] = 1;
        convergence[n] = std::max(convergence[n], c);
        convergence[o] = std::max(convergence[o], c);
      }
    }

  // Strength: c · (1 − d²/D²)² of the distance d to convergent boundary nodes (the largest),
  // D the folds' reach, times min(1, 4 d' / D) of the distance d' to any boundary node, so it
  // is 0 on every boundary and rises over D / 4 (folds set back from the boundary, as ranges
  // are behind a subduction; no step where plates meet).
  const double reach = plates_.foldReach;
  const double rise = 0.25 * reach;
  std::vector<double> converging(nodes, 0.0), apart(nodes, rise);
  const int window = static_cast<int>(std::ceil(reach * inverseSpacing_));
  for (int j = 0; j < ny_; ++j)
    for (int i = 0; i < nx_; ++i) {
      const std::size_t b =
          static_cast<std::size_t>(j) * static_cast<std::size_t>(nx_) + static_cast<std::size_t>(i);
      if (!boundary[b])
        continue;
      const Vec2 at = nodeAt(i, j);
      for (int y = std::max(0, j - window); y <= std::min(ny_ - 1, j + window); ++y)
        for (int x = std::max(0, i - window); x <= std::min(nx_ - 1, i + window); ++x) {
          const std::size_t n = static_cast<std::size_t>(y) * static_cast<std::size_t>(nx_) +
                                static_cast<std::size_t>(x);
          const double d2 = geometry::lengthSquared(nodeAt(x, y) - at);
          if (d2 < rise * rise)
            apart[n] = std::min(apart[n], std::sqrt(d2));
          if (convergence[b] > 0.0 && d2 < reach * reach) {
            const double u = 1.0 - d2 / (reach * reach);
            converging[n] = std::max(converging[n], convergence[b] * u * u);
          }
        }
    }
  strength_.resize(nodes);
  for (std::size_t n = 0; n < nodes; ++n)
    strength_[n] = converging[n] * std::min(1.0, apart[n] / rise);

  // Amplitude: a share of the drawn mountains' mean height.
  double heights = 0.0, drawn = 0.0;
  for (const input::MountainFeature& f : mountains)
    if (f.elevation) {
      heights += *f.elevation;
      drawn += 1.0;
    }
  const double height = drawn > 0.0 ? heights / drawn : kDefaultMountainHeight;
  amplitude_ = std::clamp(TectonicFolds::kReliefShare * height, TectonicFolds::kMinAmplitude,
                          TectonicFolds::kMaxAmplitude);
}

Folds::Cell Folds::cellAt(Vec2 p) const noexcept {
  double fx = (p.x - origin_.x) * inverseSpacing_, fy = (p.y - origin_.y) * inverseSpacing_;
  fx = fx > 0.0 ? fx : 0.0; // NaN: 0
  fy = fy > 0.0 ? fy : 0.0;
  fx = fx < nx_ - 1 ? fx : nx_ - 1;
  fy = fy < ny_ - 1 ? fy : ny_ - 1;
  const int i = std::min(static_cast<int>(fx), nx_ - 2),
            j = std::min(static_cast<int>(fy), ny_ - 2);
  const std::size_t n =
      static_cast<std::size_t>(j) * static_cast<std::size_t>(nx_) + static_cast<std::size_t>(i);
  const auto up = static_cast<std::size_t>(nx_);
  return {{n, n + 1, n + up, n + up + 1}, fx - i, fy - j};
}

double Folds::bilinear(const Cell& c) const noexcept {
  return (1.0 - c.ty) * ((1.0 - c.tx) * strength_[c.corners[0]] + c.tx * strength_[c.corners[1]]) +
         c.ty * ((1.0 - c.tx) * strength_[c.corners[2]] + c.tx * strength_[c.corners[3]]);
}

double Folds::strength(Vec2 p) const noexcept {
  return bilinear(cellAt(p));
}

Folds::Frame Folds::frame(Vec2 p) const noexcept {
  const Cell cell = cellAt(p);
  const std::size_t(&corners)[4] = cell.corners;
  // Nodes of positive strength around a point are all of one plate (any two nodes of a cell
  // in different plates make every node of the cell a boundary node or the neighbour of one).
  std::size_t folded = 4;
  for (std::size_t c = 0; c < 4; ++c)
    if (strength_[corners[c]] > 0.0) {
      folded = corners[c];
      break;
    }
  if (folded == 4)
    return {}; // most of the land: one lookup
  Frame f;
  f.strength = bilinear(cell);
  const std::uint32_t plate = plate_[folded];
  const Vec2 v = along_[plate];
  f.along = p.x * v.x + p.y * v.y;
  f.across = p.y * v.x - p.x * v.y;
  f.offset = 101.3 * plate;
  return f;
}

} // namespace strahler::construction::detail
