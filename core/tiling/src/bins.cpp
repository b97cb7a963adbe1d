#include "bins.h"

namespace strahler::tiling {

void Bins::runBoxes(const SampleGrid& grid, std::vector<geometry::Aabb>& boxes) {
  const auto width = static_cast<std::size_t>(grid.width);
  boxes.clear();
  boxes.reserve((width + base::kLanes - 1) / base::kLanes * static_cast<std::size_t>(grid.height));
  for (std::size_t row = 0; row < static_cast<std::size_t>(grid.height); ++row)
    for (std::size_t c = 0; c < width; c += base::kLanes) {
      // Each point's (x, y) as a two-lane vector: the box is their lane-wise least and
      // greatest (point by point through an Aabb costs several times more).
      using Pair = base::Vectors<2>::Doubles;
      const std::size_t first = row * width + c,
                        end = row * width + std::min(width, c + base::kLanes);
      Pair least{grid.points[first].x, grid.points[first].y}, greatest = least;
      for (std::size_t k = first + 1; k < end; ++k) {
        const Pair p{grid.points[k].x, grid.points[k].y};
        least = p < least ? p : least;
        greatest = p > greatest ? p : greatest;
      }
      boxes.push_back({{least[0], least[1]}, {greatest[0], greatest[1]}});
    }
}

void Bins::reset(const SampleGrid& grid, std::span<const geometry::Aabb> runBoxes, int groups,
                 int rows, const geometry::Aabb& reach, bool withTerrain) {
  groups_ = groups;
  rows_ = rows;
  const int runs = (grid.width + base::kLanes - 1) / base::kLanes;
  nx_ = (runs + groups - 1) / groups;
  ny_ = (grid.height + rows - 1) / rows;
  if (groups == 1 && rows == 1) {
    boxView_ = runBoxes; // a bin per run: the runs' own boxes
  } else {
    boxes_.assign(count(), geometry::Aabb{});
    boxView_ = boxes_;
    std::vector<std::size_t> columnOfRun(static_cast<std::size_t>(runs));
    for (int q = 0; q < runs; ++q)
      columnOfRun[static_cast<std::size_t>(q)] = static_cast<std::size_t>(q / groups);
    // Corners as two-lane vectors (an Aabb grown point by point costs several times more).
    using Pair = base::Vectors<2>::Doubles;
    for (int r = 0; r < grid.height; ++r) {
      geometry::Aabb* binRow = boxes_.data() + static_cast<std::size_t>(r / rows) * nx_;
      const geometry::Aabb* run = runBoxes.data() + static_cast<std::size_t>(r) * runs;
      for (std::size_t q = 0; q < columnOfRun.size(); ++q) {
        geometry::Aabb& box = binRow[columnOfRun[q]];
        const Pair least{box.min.x, box.min.y}, greatest{box.max.x, box.max.y};
        const Pair low{run[q].min.x, run[q].min.y}, high{run[q].max.x, run[q].max.y};
        const Pair min = low < least ? low : least, max = high > greatest ? high : greatest;
        box = {{min[0], min[1]}, {max[0], max[1]}};
      }
    }
  }
  std::vector<double> colLo(nx_, kInf), colHi(nx_, -kInf), rowLo(ny_, kInf), rowHi(ny_, -kInf);
  for (int j = 0; j < ny_; ++j)
    for (int i = 0; i < nx_; ++i) {
      const geometry::Aabb& b = box(i, j);
      colLo[i] = std::min(colLo[i], b.min.x);
      colHi[i] = std::max(colHi[i], b.max.x);
      rowLo[j] = std::min(rowLo[j], b.min.y);
      rowHi[j] = std::max(rowHi[j], b.max.y);
    }
  columns_.emplace(std::move(colLo), std::move(colHi));
  rows_run_.emplace(std::move(rowLo), std::move(rowHi));
  reachable_.clear();
  if (!monotone())
    for (std::size_t b = 0; b < count(); ++b)
      if (!boxView_[b].empty() && boxView_[b].intersects(reach))
        reachable_.push_back(b);
  if (withTerrain) {
    terrain_.resize(std::max(terrain_.size(), count()));
    for (std::size_t b = 0; b < count(); ++b)
      terrain_[b].clear();
  }
  riverBegin_.assign(count() + 1, 0);
  lastRiver_.assign(count(), kNone);
  riverPairs_.clear();
}

void Bins::addRiverInRange(const Range& range, std::uint32_t id,
                           std::span<const geometry::Aabb> chunks, double reach) {
  const auto count = static_cast<std::size_t>(range.size());
  std::array<double, kRangeBins> lowX, highX, lowY, highY;
  std::array<std::uint32_t, kRangeBins> first, end, bin;
  std::size_t r = 0;
  for (int j = range.j0; j < range.j1; ++j)
    for (int i = range.i0; i < range.i1; ++i, ++r) {
      const geometry::Aabb& b = box(i, j); // empty boxes are +inf..-inf: never met
      lowX[r] = b.min.x;
      highX[r] = b.max.x;
      lowY[r] = b.min.y;
      highY[r] = b.max.y;
      first[r] = std::numeric_limits<std::uint32_t>::max();
      end[r] = 0;
      bin[r] = static_cast<std::uint32_t>(at(i, j));
    }
  // The tests in two-lane vectors and the updates by masks: written as choices, GCC
  // compiled them to branches, which mispredicted about every other time.
  using Pair = base::Vectors<2>::Doubles;
  for (std::uint32_t c = 0; c < chunks.size(); ++c) {
    const geometry::Aabb near = chunks[c].expanded(reach);
    const Pair nearMin{near.min.x, near.min.y}, nearMax{near.max.x, near.max.y};
    for (r = 0; r < count; ++r) {
      const auto both = (Pair{highX[r], highY[r]} >= nearMin) & (Pair{lowX[r], lowY[r]} <= nearMax);
      const std::uint32_t keep = 0u - static_cast<std::uint32_t>((both[0] & both[1]) != 0);
      first[r] = std::min(first[r], c | ~keep);
      end[r] = (end[r] & ~keep) | ((c + 1) & keep);
    }
  }
  for (r = 0; r < count; ++r)
    if (end[r] > 0)
      riverPairs_.push_back({bin[r], {id, first[r], end[r]}});
}

template <class T>
void Bins::sortByBin(std::span<const std::pair<std::uint32_t, T>> pairs,
                     std::vector<std::uint32_t>& begin, std::vector<T>& items) {
  for (const auto& [bin, item] : pairs)
    ++begin[bin + 1];
  for (std::size_t b = 0; b < count(); ++b)
    begin[b + 1] += begin[b];
  items.resize(pairs.size());
  next_.assign(begin.begin(), begin.end() - 1);
  for (const auto& [bin, item] : pairs)
    items[next_[bin]++] = item;
}

void Bins::finish() {
  sortByBin<construction::World::RiverCandidate>(riverPairs_, riverBegin_, rivers_);
}

} // namespace strahler::tiling
