#include "strahler/tiling/tile_evaluator.h"

#include <algorithm>
#include <cmath>
#include <span>
#include <utility>

namespace strahler::tiling {
namespace {

using geometry::Aabb;
using geometry::Vec2;

/// Candidate lists of every bin, flattened: built from (bin, id) pairs by a stable counting
/// sort, so each list keeps the ascending insertion order, with two allocations per tile
/// instead of one per bin.
class BinLists {
public:
  void add(std::size_t bin, std::uint32_t id) { pairs_.push_back({bin, id}); }
  void finish(std::size_t bins) {
    begin_.assign(bins + 1, 0);
    for (const auto& [bin, id] : pairs_)
      ++begin_[bin + 1];
    for (std::size_t b = 0; b < bins; ++b)
      begin_[b + 1] += begin_[b];
    ids_.resize(pairs_.size());
    std::vector<std::uint32_t> next(begin_.begin(), begin_.end() - 1);
    for (const auto& [bin, id] : pairs_)
      ids_[next[bin]++] = id;
    pairs_.clear();
    pairs_.shrink_to_fit();
  }
  std::span<const std::uint32_t> operator[](std::size_t bin) const noexcept {
    return {ids_.data() + begin_[bin], ids_.data() + begin_[bin + 1]};
  }

private:
  std::vector<std::pair<std::size_t, std::uint32_t>> pairs_;
  std::vector<std::uint32_t> begin_;
  std::vector<std::uint32_t> ids_;
};

/// A square grid of bins over a tile's samples; each bin lists (ascending) the primitives
/// whose support meets it, and whether it lies wholly inland, beyond the coast band.
class Bins {
public:
  Bins(const Aabb& bounds, int perSide) : bounds_(bounds), n_(perSide) {
    const Vec2 size = bounds.size();
    cell_ = {std::max(size.x, 1e-9) / n_, std::max(size.y, 1e-9) / n_};
    const auto count = static_cast<std::size_t>(n_) * static_cast<std::size_t>(n_);
    coast_.assign(count, construction::World::Coast::kUnknown);
  }

  int of(double v, double origin, double cell) const noexcept {
    return std::clamp(static_cast<int>(std::floor((v - origin) / cell)), 0, n_ - 1);
  }
  std::size_t binAt(Vec2 p) const noexcept {
    return static_cast<std::size_t>(of(p.y, bounds_.min.y, cell_.y)) *
               static_cast<std::size_t>(n_) +
           static_cast<std::size_t>(of(p.x, bounds_.min.x, cell_.x));
  }
  Aabb box(int i, int j) const noexcept {
    const Vec2 lo{bounds_.min.x + i * cell_.x, bounds_.min.y + j * cell_.y};
    return {lo, lo + cell_};
  }

  /// Adds primitive `id` to every bin its box meets for which `meets(binBox)` holds.
  template <class Meets>
  void add(BinLists& lists, const Aabb& support, std::uint32_t id, Meets&& meets) {
    if (!support.intersects(bounds_))
      return;
    const int i0 = of(support.min.x, bounds_.min.x, cell_.x),
              i1 = of(support.max.x, bounds_.min.x, cell_.x);
    const int j0 = of(support.min.y, bounds_.min.y, cell_.y),
              j1 = of(support.max.y, bounds_.min.y, cell_.y);
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i)
        if (meets(box(i, j)))
          lists.add(static_cast<std::size_t>(j) * static_cast<std::size_t>(n_) +
                        static_cast<std::size_t>(i),
                    id);
  }
  void finish() {
    const auto count = static_cast<std::size_t>(n_) * static_cast<std::size_t>(n_);
    terrain_.finish(count);
    rivers_.finish(count);
  }

  int perSide() const noexcept { return n_; }
  BinLists& terrain() noexcept { return terrain_; }
  BinLists& rivers() noexcept { return rivers_; }
  std::vector<construction::World::Coast>& coast() noexcept { return coast_; }

private:
  Aabb bounds_;
  int n_;
  Vec2 cell_;
  BinLists terrain_, rivers_;
  std::vector<construction::World::Coast> coast_;
};

/// Squared distance from p to box b (0 inside).
double distanceToBox2(Vec2 p, const Aabb& b) {
  const double dx = std::max({b.min.x - p.x, 0.0, p.x - b.max.x});
  const double dy = std::max({b.min.y - p.y, 0.0, p.y - b.max.y});
  return dx * dx + dy * dy;
}

double distanceToBox(Vec2 p, const Aabb& b) {
  const double dx = std::max({b.min.x - p.x, 0.0, p.x - b.max.x});
  const double dy = std::max({b.min.y - p.y, 0.0, p.y - b.max.y});
  return std::hypot(dx, dy);
}

/// Bins of about kBinSide metres (below the scale of a terrain primitive, so most candidates
/// of a bin do cover its samples), at most kMaxBins per side.
/// (Finer bins at low zoom cost more to build, and to classify by coast, than they save.)
constexpr int kMaxBins = 128;
int binsPerSide(const Aabb& bounds) {
  constexpr double kBinSide = 60.0;
  const double extent = std::max(bounds.size().x, bounds.size().y);
  return static_cast<int>(std::clamp(std::round(extent / kBinSide), 1.0, double(kMaxBins)));
}

} // namespace

TileEvaluator::TileEvaluator(const construction::World& world)
    : world_(world), blocks_(world.data()) {}

construction::World::Coast TileEvaluator::coastOf(Vec2 center, double halfDiagonal) const {
  using Coast = construction::World::Coast;
  const geometry::PolygonIndex& land = world_.land();
  if (distanceToBox(center, land.bounds()) >= construction::World::shelfReach() + halfDiagonal)
    return Coast::kFarSea; // cheap: far from the land's bounding box
  const bool inside = land.contains(center);
  const double reach =
      (inside ? construction::CoastShape::kBand : construction::World::shelfReach()) + halfDiagonal;
  if (land.distanceToBoundary(center, reach) < reach)
    return Coast::kUnknown;
  return inside ? Coast::kInland : Coast::kFarSea;
}

std::vector<double> TileEvaluator::evaluate(const SampleGrid& grid, TileStats* stats) const {
  const construction::WorldData& data = world_.data();
  const std::vector<std::uint32_t> blocks = blocks_.blocksMeeting(grid.bounds);
  Bins bins(grid.bounds, binsPerSide(grid.bounds));
  TileStats local;
  local.blocks = blocks.size();
  // Blocks are ascending and their ranges contiguous, so primitive ids arrive ascending.
  for (std::uint32_t b : blocks) {
    const construction::BlockPrimitives& r = data.blocks[b];
    for (std::uint32_t i = r.terrainBegin; i < r.terrainEnd; ++i) {
      const primitives::TerrainPrimitive& t = data.terrain[i];
      // Squared, without hypot: the slack (1e-9 relative) only ever admits extra candidates,
      // which are harmless (w = 0 beyond the radius).
      const double reach2 = t.radius * t.radius * (1.0 + 1e-9);
      bins.add(bins.terrain(), Aabb{t.center, t.center}.expanded(t.radius), i,
               [&](const Aabb& box) { return distanceToBox2(t.center, box) <= reach2; });
    }
    for (std::uint32_t i = r.riverBegin; i < r.riverEnd; ++i)
      bins.add(bins.rivers(), primitives::supportBox(data.rivers[i]), i,
               [](const Aabb&) { return true; });
    local.terrainPrimitives += r.terrainEnd - r.terrainBegin;
    local.riverPrimitives += r.riverEnd - r.riverBegin;
  }
  bins.finish();
  for (int j = 0; j < bins.perSide(); ++j)
    for (int i = 0; i < bins.perSide(); ++i) {
      const Aabb box = bins.box(i, j);
      const double halfDiagonal = 0.5 * length(box.size());
      bins.coast()[static_cast<std::size_t>(j * bins.perSide() + i)] =
          coastOf(box.center(), halfDiagonal);
    }
  std::vector<double> heights(grid.points.size());
  for (int row = 0; row < grid.height; ++row) {
    const double spacing = grid.rowSpacing[static_cast<std::size_t>(row)];
    for (int col = 0; col < grid.width; ++col) {
      const std::size_t k = static_cast<std::size_t>(row) * static_cast<std::size_t>(grid.width) +
                            static_cast<std::size_t>(col);
      const Vec2 p = grid.points[k];
      const std::size_t bin = bins.binAt(p);
      heights[k] =
          world_
              .evaluateFrom(p, spacing, bins.terrain()[bin], bins.rivers()[bin], bins.coast()[bin])
              .height;
    }
  }
  if (stats)
    *stats = local;
  return heights;
}

} // namespace strahler::tiling
