#pragma once

// Private to the tiling module: the bins a tile's samples are grouped into, each listing the
// primitives that may shape its samples (TileEvaluator's binning step).

#include "strahler/base/lanes.h"
#include "strahler/construction/world.h"
#include "strahler/geometry/aabb.h"
#include "strahler/tiling/candidate_filters.h"
#include "strahler/tiling/tile_scheme.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <utility>
#include <vector>

namespace strahler::tiling {

/// Which of a sequence of intervals [lo[i], hi[i]] meet [a, b]: when both ends are monotone in
/// the same direction (rows and columns of a tile, except for tiles wrapping half the globe)
/// they form a range, found by walking from where evenly spaced intervals would put a and b
/// (a step or two: twice as fast as binary searches here); otherwise every index is returned
/// (the caller tests each).
class IntervalRun {
public:
  /// The intervals [lo[i], hi[i]] (lo and hi of one size).
  IntervalRun(std::vector<double> lo, std::vector<double> hi)
      : lo_(std::move(lo)), hi_(std::move(hi)) {
    increasing_ = std::is_sorted(lo_.begin(), lo_.end()) && std::is_sorted(hi_.begin(), hi_.end());
    decreasing_ =
        std::is_sorted(lo_.rbegin(), lo_.rend()) && std::is_sorted(hi_.rbegin(), hi_.rend());
    if (lo_.size() > 1) {
      origin_ = lo_.front();
      const double step = (lo_.back() - lo_.front()) / static_cast<double>(lo_.size() - 1);
      perIndex_ = step != 0.0 ? 1.0 / step : 0.0;
    }
  }
  /// Whether meeting() finds exactly the intervals that meet.
  bool monotone() const noexcept { return increasing_ || decreasing_; }
  /// [first, last) holding every i whose interval meets [a, b].
  std::pair<int, int> meeting(double a, double b) const noexcept {
    if (increasing_)
      return {walk(hi_, a, [&](double h) { return h < a; }),
              walk(lo_, b, [&](double l) { return l <= b; })};
    if (decreasing_)
      return {walk(lo_, b, [&](double l) { return l > b; }),
              walk(hi_, a, [&](double h) { return h >= a; })};
    return {0, static_cast<int>(lo_.size())};
  }

private:
  /// The partition point of v under `before`, walked to from where evenly spaced intervals
  /// would put coordinate x (a step or two: rows and columns are nearly even).
  template <class Before> int walk(const std::vector<double>& v, double x, Before&& before) const {
    const auto n = static_cast<int>(v.size());
    const double guess = (x - origin_) * perIndex_;
    int i = guess > 0.0 ? (guess < n ? static_cast<int>(guess) : n) : 0;
    while (i > 0 && !before(v[static_cast<std::size_t>(i - 1)]))
      --i;
    while (i < n && before(v[static_cast<std::size_t>(i)]))
      ++i;
    return i;
  }

  std::vector<double> lo_, hi_;
  bool increasing_ = false, decreasing_ = false;
  double origin_ = 0.0, perIndex_ = 0.0; // index ≈ (x − origin) · perIndex
};

/// A list of ids, each with a key (a float), appended to without a branch on whether to keep
/// each: the entry is written past the end, which then moves or not. Keeps its storage when
/// cleared.
class IdList {
public:
  /// Empties the list, keeping its storage.
  void clear() noexcept { size_ = 0; }
  /// Appends `id` with `key` if `keep`.
  void appendIf(std::uint32_t id, float key, bool keep) {
    if (size_ == capacity_)
      grow();
    ids_[size_] = id;
    keys_[size_] = key;
    size_ += static_cast<std::uint32_t>(keep);
  }
  /// Where to write up to `most` more entries: write them there, then call appended().
  struct Room {
    std::uint32_t* ids;
    float* keys;
  };
  /// Room for `most` entries past the end (grown when needed).
  Room room(std::size_t most) {
    while (size_ + most > capacity_)
      grow();
    return {ids_.get() + size_, keys_.get() + size_};
  }
  /// Keeps the first `count` entries written into room().
  void appended(std::size_t count) noexcept { size_ += static_cast<std::uint32_t>(count); }
  /// The ids kept, in the order appended.
  std::span<const std::uint32_t> items() const noexcept { return {ids_.get(), size_}; }
  /// Their keys, in the same order.
  std::span<const float> keys() const noexcept { return {keys_.get(), size_}; }

private:
  void grow() {
    const std::uint32_t capacity = std::max<std::uint32_t>(16, 2 * capacity_);
    auto ids = std::make_unique_for_overwrite<std::uint32_t[]>(capacity);
    auto keys = std::make_unique_for_overwrite<float[]>(capacity);
    std::copy_n(ids_.get(), size_, ids.get());
    std::copy_n(keys_.get(), size_, keys.get());
    ids_ = std::move(ids);
    keys_ = std::move(keys);
    capacity_ = capacity;
  }

  std::unique_ptr<std::uint32_t[]> ids_;
  std::unique_ptr<float[]> keys_;
  std::uint32_t size_ = 0, capacity_ = 0;
};

/// Most bins of a river's support that Bins::addRiverInRange() takes.
constexpr int kRangeBins = 64;

/// Bins over a tile's samples in index space: a bin is `groups` runs of base::kLanes samples
/// of a row times `rows` rows, so every run of kLanes samples lies in one bin and is evaluated
/// in one vector pass. Each bin lists (ascending) the terrain primitives whose support meets
/// the box of its samples, and the rivers a run of whose curve comes near it, with the span
/// of such runs.
class Bins {
public:
  /// The box of each run of base::kLanes samples of each row of `grid` (row-major) into
  /// `boxes`.
  static void runBoxes(const SampleGrid& grid, std::vector<geometry::Aabb>& boxes);

  /// Empty bins, to be reset() for a tile.
  Bins() = default;
  /// Makes these the bins over `grid`, whose run boxes are `runBoxes`, with nothing added;
  /// no primitive reaches outside `reach` (used when rows or columns are not monotone in the
  /// local frame: tiles spanning half the globe). Arrays keep their capacity from tile to tile.
  /// Terrain lists are cleared only `withTerrain` (bins that take rivers only have none).
  /// Bins of one run each (groups and rows 1) use `runBoxes` as their boxes: it must outlive
  /// their use.
  void reset(const SampleGrid& grid, std::span<const geometry::Aabb> runBoxes, int groups, int rows,
             const geometry::Aabb& reach, bool withTerrain);

  /// How many bins: perRow() · perColumn().
  std::size_t count() const noexcept { return static_cast<std::size_t>(nx_) * ny_; }
  /// The bin holding the sample at (row, col) of the grid.
  std::size_t binOf(int row, int col) const noexcept {
    return static_cast<std::size_t>(row / rows_) * nx_ +
           static_cast<std::size_t>(col / base::kLanes / groups_);
  }
  /// The box of the samples of bin (i, j): column i, row j (empty for a bin of no sample).
  const geometry::Aabb& box(int i, int j) const noexcept {
    return boxView_[static_cast<std::size_t>(j) * nx_ + i];
  }

  /// Bins [i0, i1) × [j0, j1) of a box: columns and rows that meet it (all of them when
  /// rows or columns are not monotone).
  struct Range {
    int i0 = 0, i1 = 0, j0 = 0, j1 = 0;
    int size() const noexcept { return (i1 - i0) * (j1 - j0); }
  };
  /// The bins whose column and row meet `box`.
  Range rangeOf(const geometry::Aabb& box) const noexcept {
    if (!monotone())
      return {0, nx_, 0, ny_};
    const auto [i0, i1] = columns_->meeting(box.min.x, box.max.x);
    const auto [j0, j1] = rows_run_->meeting(box.min.y, box.max.y);
    return {i0, i1, j0, j1};
  }
  /// Whether rows and columns are monotone (bins are then found by ranges).
  bool monotone() const noexcept { return columns_->monotone() && rows_run_->monotone(); }
  /// The bin at (i, j).
  std::size_t at(int i, int j) const noexcept { return static_cast<std::size_t>(j) * nx_ + i; }

  /// Calls f(bin) for every bin of `range` (that of a box holding `support`) whose box meets
  /// `support` and satisfies meets(box).
  template <class Meets, class F>
  void forEachBin(const Range& range, const geometry::Aabb& support, Meets&& meets, F&& f) const {
    if (!monotone()) {
      for (const std::size_t bin : reachable_)
        if (boxView_[bin].intersects(support) && meets(boxView_[bin]))
          f(bin);
      return;
    }
    for (int j = range.j0; j < range.j1; ++j)
      for (int i = range.i0; i < range.i1; ++i) {
        const geometry::Aabb& b = box(i, j);
        if (!b.empty() && b.intersects(support) && meets(b))
          f(at(i, j));
      }
  }
  /// forEachBin() over the range of `support` itself.
  template <class Meets, class F>
  void forEachBin(const geometry::Aabb& support, Meets&& meets, F&& f) const {
    forEachBin(rangeOf(support), support, meets, f);
  }

  /// Adds terrain primitive `id`, whose key is `key` (TerrainDiscs::keyY), to the list of
  /// `bin`. Lists keep the order of addition.
  void addTerrain(std::size_t bin, std::uint32_t id, float key) {
    terrain_[bin].appendIf(id, key, true);
  }
  /// Adds terrain primitive `id` to every bin of `range` (monotone bins) whose box its disc
  /// (centre, squared radius with slack) meets; without a branch per bin, which would be
  /// mispredicted about every other time.
  void addTerrainDisc(const Range& range, const TerrainDiscs& discs, std::uint32_t id) {
    const geometry::Vec2 center = discs.center(id);
    for (int j = range.j0; j < range.j1; ++j)
      for (int i = range.i0; i < range.i1; ++i) {
        // Empty boxes are +inf..-inf: never met.
        terrain_[at(i, j)].appendIf(id, discs.keyY[id],
                                    squaredDistanceToBox(center, box(i, j)) <= discs.reach2[id]);
      }
  }
  /// Adds terrain primitives first, first + 1, … first + count − 1 to every bin of `range`
  /// (monotone bins) whose box their disc meets: bin after bin, in vector code where the CPU
  /// has it (keepDiscsMeeting()).
  void addTerrainDiscs(const Range& range, const TerrainDiscs& discs, std::uint32_t first,
                       std::size_t count, construction::InstructionSet set) {
    for (int j = range.j0; j < range.j1; ++j)
      for (int i = range.i0; i < range.i1; ++i) {
        IdList& list = terrain_[at(i, j)];
        const IdList::Room out = list.room(count + kFilterOverrun);
        list.appended(keepDiscsMeeting(discs, first, count, box(i, j), out.ids, out.keys, set));
      }
  }
  /// Adds river primitive `id`, whose support meets the bins of `range` (at most kRangeBins
  /// monotone bins), to each of them that a run of its curve comes within `reach` of, with
  /// the span of such runs (`chunks`: the runs' boxes). Every run is tested against every bin
  /// of the range by its box, without a branch (the same bins for all the river's runs, so the
  /// loops are predicted); a run reaching past the support adds nothing there, as points
  /// outside it are not searched. Rivers must come in ascending order.
  void addRiverInRange(const Range& range, std::uint32_t id, std::span<const geometry::Aabb> chunks,
                       double reach);
  /// Adds runs [first, end) of river primitive `id`'s curve to `bin`: rivers must come in
  /// ascending order and each river's runs ascending.
  void addRiverChunks(std::size_t bin, std::uint32_t id, std::uint32_t first, std::uint32_t end) {
    std::size_t& last = lastRiver_[bin];
    if (last != kNone && riverPairs_[last].second.id == id) {
      riverPairs_[last].second.endChunk = end;
      return;
    }
    last = riverPairs_.size();
    riverPairs_.push_back({static_cast<std::uint32_t>(bin), {id, first, end}});
  }
  /// Sorts the rivers added into the bins' lists; must follow the last addition of a river.
  void finish();

  /// The terrain primitives listed in `bin`, in the order added.
  std::span<const std::uint32_t> terrain(std::size_t bin) const noexcept {
    return terrain_[bin].items();
  }
  /// The y of each of terrain(bin)'s centres, rounded to float.
  std::span<const float> terrainKeys(std::size_t bin) const noexcept {
    return terrain_[bin].keys();
  }
  /// The rivers listed in `bin`, ascending, with their runs near it (after finish()).
  std::span<const construction::World::RiverCandidate> rivers(std::size_t bin) const noexcept {
    return {rivers_.data() + riverBegin_[bin], rivers_.data() + riverBegin_[bin + 1]};
  }
  /// Bins per row of bins (columns).
  int perRow() const noexcept { return nx_; }
  /// Bins per column of bins (rows).
  int perColumn() const noexcept { return ny_; }

private:
  static constexpr double kInf = std::numeric_limits<double>::infinity();
  static constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
  template <class T> using Pairs = std::vector<std::pair<std::uint32_t, T>>; // (bin, item)

  /// Stable counting sort of (bin, item) pairs into per-bin lists.
  template <class T>
  void sortByBin(std::span<const std::pair<std::uint32_t, T>> pairs,
                 std::vector<std::uint32_t>& begin, std::vector<T>& items);

  int groups_ = 1, rows_ = 1, nx_ = 0, ny_ = 0;
  std::vector<geometry::Aabb> boxes_;
  // The bins' boxes: boxes_, or the run boxes given to reset().
  std::span<const geometry::Aabb> boxView_;
  std::optional<IntervalRun> columns_, rows_run_;
  std::vector<std::size_t> reachable_; // bins meeting `reach`, when not monotone
  Pairs<construction::World::RiverCandidate> riverPairs_;
  std::vector<std::size_t> lastRiver_; // per bin: its last entry in riverPairs_, or kNone
  std::vector<IdList> terrain_; // per bin (the first count(); more are kept for larger tiles)
  std::vector<std::uint32_t> riverBegin_;
  std::vector<std::uint32_t> next_; // sortByBin(): where each bin's next item goes
  std::vector<construction::World::RiverCandidate> rivers_;
};

} // namespace strahler::tiling
