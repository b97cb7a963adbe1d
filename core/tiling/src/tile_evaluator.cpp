#include "strahler/tiling/tile_evaluator.h"

#include "strahler/base/lanes.h"
#include "strahler/tiling/candidate_filters.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <utility>

namespace strahler::tiling {
namespace {

using geometry::Aabb;
using geometry::Vec2;

/// Which of a sequence of intervals [lo[i], hi[i]] meet [a, b]: when both ends are monotone in
/// the same direction (rows and columns of a tile, except for tiles wrapping half the globe)
/// they form a range, found by walking from where evenly spaced intervals would put a and b
/// (a step or two: twice as fast as binary searches here); otherwise every index is returned
/// (the caller tests each).
class IntervalRun {
public:
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

/// Distance from p to box b (0 inside).
double distanceToBox(Vec2 p, const Aabb& b) {
  const Vec2 gap = gapsToBox(p, b);
  return std::hypot(gap.x, gap.y);
}

/// A list of ids, each with a key (a float), appended to without a branch on whether to keep
/// each: the entry is written past the end, which then moves or not. Keeps its storage when
/// cleared.
class IdList {
public:
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
  static void runBoxes(const SampleGrid& grid, std::vector<Aabb>& boxes) {
    const auto width = static_cast<std::size_t>(grid.width);
    boxes.clear();
    boxes.reserve((width + base::kLanes - 1) / base::kLanes *
                  static_cast<std::size_t>(grid.height));
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

  /// Empty bins, to be reset() for a tile.
  Bins() = default;
  /// Makes these the bins over `grid`, whose run boxes are `runBoxes`, with nothing added;
  /// no primitive reaches outside `reach` (used when rows or columns are not monotone in the
  /// local frame: tiles spanning half the globe). Arrays keep their capacity from tile to tile.
  /// Terrain lists are cleared only `withTerrain` (bins that take rivers only have none).
  /// Bins of one run each (groups and rows 1) use `runBoxes` as their boxes: it must outlive
  /// their use.
  void reset(const SampleGrid& grid, std::span<const Aabb> runBoxes, int groups, int rows,
             const Aabb& reach, bool withTerrain) {
    groups_ = groups;
    rows_ = rows;
    const int runs = (grid.width + base::kLanes - 1) / base::kLanes;
    nx_ = (runs + groups - 1) / groups;
    ny_ = (grid.height + rows - 1) / rows;
    if (groups == 1 && rows == 1) {
      boxView_ = runBoxes; // a bin per run: the runs' own boxes
    } else {
      boxes_.assign(count(), Aabb{});
      boxView_ = boxes_;
      std::vector<std::size_t> columnOfRun(static_cast<std::size_t>(runs));
      for (int q = 0; q < runs; ++q)
        columnOfRun[static_cast<std::size_t>(q)] = static_cast<std::size_t>(q / groups);
      // Corners as two-lane vectors (an Aabb grown point by point costs several times more).
      using Pair = base::Vectors<2>::Doubles;
      for (int r = 0; r < grid.height; ++r) {
        Aabb* binRow = boxes_.data() + static_cast<std::size_t>(r / rows) * nx_;
        const Aabb* run = runBoxes.data() + static_cast<std::size_t>(r) * runs;
        for (std::size_t q = 0; q < columnOfRun.size(); ++q) {
          Aabb& box = binRow[columnOfRun[q]];
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
        const Aabb& b = box(i, j);
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

  std::size_t count() const noexcept { return static_cast<std::size_t>(nx_) * ny_; }
  std::size_t binOf(int row, int col) const noexcept {
    return static_cast<std::size_t>(row / rows_) * nx_ +
           static_cast<std::size_t>(col / base::kLanes / groups_);
  }
  const Aabb& box(int i, int j) const noexcept {
    return boxView_[static_cast<std::size_t>(j) * nx_ + i];
  }

  /// Bins [i0, i1) × [j0, j1) of a box: columns and rows that meet it (all of them when
  /// rows or columns are not monotone).
  struct Range {
    int i0 = 0, i1 = 0, j0 = 0, j1 = 0;
    int size() const noexcept { return (i1 - i0) * (j1 - j0); }
  };
  Range rangeOf(const Aabb& box) const noexcept {
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
  void forEachBin(const Range& range, const Aabb& support, Meets&& meets, F&& f) const {
    if (!monotone()) {
      for (const std::size_t bin : reachable_)
        if (boxView_[bin].intersects(support) && meets(boxView_[bin]))
          f(bin);
      return;
    }
    for (int j = range.j0; j < range.j1; ++j)
      for (int i = range.i0; i < range.i1; ++i) {
        const Aabb& b = box(i, j);
        if (!b.empty() && b.intersects(support) && meets(b))
          f(at(i, j));
      }
  }
  /// forEachBin() over the range of `support` itself.
  template <class Meets, class F> void forEachBin(const Aabb& support, Meets&& meets, F&& f) const {
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
    const Vec2 center = discs.center(id);
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
  void addRiverInRange(const Range& range, std::uint32_t id, std::span<const Aabb> chunks,
                       double reach) {
    const auto count = static_cast<std::size_t>(range.size());
    std::array<double, kRangeBins> lowX, highX, lowY, highY;
    std::array<std::uint32_t, kRangeBins> first, end, bin;
    std::size_t r = 0;
    for (int j = range.j0; j < range.j1; ++j)
      for (int i = range.i0; i < range.i1; ++i, ++r) {
        const Aabb& b = box(i, j); // empty boxes are +inf..-inf: never met
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
      const Aabb near = chunks[c].expanded(reach);
      const Pair nearMin{near.min.x, near.min.y}, nearMax{near.max.x, near.max.y};
      for (r = 0; r < count; ++r) {
        const auto both =
            (Pair{highX[r], highY[r]} >= nearMin) & (Pair{lowX[r], lowY[r]} <= nearMax);
        const std::uint32_t keep = 0u - static_cast<std::uint32_t>((both[0] & both[1]) != 0);
        first[r] = std::min(first[r], c | ~keep);
        end[r] = (end[r] & ~keep) | ((c + 1) & keep);
      }
    }
    for (r = 0; r < count; ++r)
      if (end[r] > 0)
        riverPairs_.push_back({bin[r], {id, first[r], end[r]}});
  }
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
  void finish() {
    sortByBin<construction::World::RiverCandidate>(riverPairs_, riverBegin_, rivers_);
  }

  std::span<const std::uint32_t> terrain(std::size_t bin) const noexcept {
    return terrain_[bin].items();
  }
  /// The y of each of terrain(bin)'s centres, rounded to float.
  std::span<const float> terrainKeys(std::size_t bin) const noexcept {
    return terrain_[bin].keys();
  }
  std::span<const construction::World::RiverCandidate> rivers(std::size_t bin) const noexcept {
    return {rivers_.data() + riverBegin_[bin], rivers_.data() + riverBegin_[bin + 1]};
  }
  int perRow() const noexcept { return nx_; }
  int perColumn() const noexcept { return ny_; }

private:
  static constexpr double kInf = std::numeric_limits<double>::infinity();
  static constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
  template <class T> using Pairs = std::vector<std::pair<std::uint32_t, T>>; // (bin, item)

  /// Stable counting sort of (bin, item) pairs into per-bin lists.
  template <class T>
  void sortByBin(std::span<const std::pair<std::uint32_t, T>> pairs,
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

  int groups_ = 1, rows_ = 1, nx_ = 0, ny_ = 0;
  std::vector<Aabb> boxes_;
  std::span<const Aabb> boxView_; // the bins' boxes: boxes_, or the run boxes given to reset()
  std::optional<IntervalRun> columns_, rows_run_;
  std::vector<std::size_t> reachable_; // bins meeting `reach`, when not monotone
  Pairs<construction::World::RiverCandidate> riverPairs_;
  std::vector<std::size_t> lastRiver_; // per bin: its last entry in riverPairs_, or kNone
  std::vector<IdList> terrain_; // per bin (the first count(); more are kept for larger tiles)
  std::vector<std::uint32_t> riverBegin_;
  std::vector<std::uint32_t> next_; // sortByBin(): where each bin's next item goes
  std::vector<construction::World::RiverCandidate> rivers_;
};

/// A block meeting at most this many bins has its primitives' bins found by testing each of
/// its bins (in vector code); more, by searching for each primitive's own range (measured
/// against 16: zoom 11 −4 %, other zooms within ±0.3 %; 256: no further gain).
constexpr int kScanBins = 64;

/// Grids of more samples than this (512²) release the per-thread scratch after evaluation.
constexpr std::size_t kKeptScratchSamples = 512 * 512;

/// A bin with more terrain candidates than this is evaluated point by point.
constexpr std::size_t kDenseBin = 1024;

/// Bins about square, of at least kBinSide metres (below the scale of a terrain primitive,
/// so most candidates of a bin do cover its samples) and never narrower than one run of
/// base::kLanes samples: (runs of a row, rows) per bin.
constexpr double kBinSide = 60.0;
std::pair<int, int> binShape(const SampleGrid& grid) {
  const Vec2 size = grid.bounds.size();
  const double dx = std::max(size.x / std::max(grid.width - 1, 1), 1e-9);
  const double dy = std::max(size.y / std::max(grid.height - 1, 1), 1e-9);
  const int runs = (grid.width + base::kLanes - 1) / base::kLanes;
  const double groups = std::clamp(std::round(kBinSide / (dx * base::kLanes)), 1.0,
                                   static_cast<double>(std::max(runs, 1)));
  const double width = groups * base::kLanes * dx;
  const double rows = std::clamp(std::round(std::max(kBinSide, width) / dy), 1.0,
                                 static_cast<double>(std::max(grid.height, 1)));
  return {static_cast<int>(groups), static_cast<int>(rows)};
}

} // namespace

TileEvaluator::TileEvaluator(const construction::World& world)
    : world_(world), blocks_(world.data()), terrainDiscs_(world.data().terrain) {}

TileEvaluator::BinShore TileEvaluator::shoreOf(const Aabb& box,
                                               std::vector<std::uint32_t>& segments) const {
  using Coast = construction::World::Coast;
  const Vec2 center = box.center();
  const double halfDiagonal = 0.5 * length(box.size());
  const double shelf = construction::World::shelfReach();
  const geometry::PolygonIndex& land = world_.land();
  if (distanceToBox(center, land.bounds()) >= shelf + halfDiagonal)
    return {Coast::kFarSea, false}; // cheap: far from the land's bounding box
  // Cells of the land's index that keep their distance from the boundary: no search.
  const geometry::PolygonIndex::Clearance clear = land.clearance(box);
  if (clear.distance >= (clear.inside ? construction::CoastShape::kBand : shelf))
    return {clear.inside ? Coast::kInland : Coast::kFarSea, clear.inside};
  const bool inside = land.contains(center);
  const double reach = (inside ? construction::CoastShape::kBand : shelf) + halfDiagonal;
  const geometry::BoundaryHit hit = land.nearestBoundary(center, reach);
  if (hit.segment < 0 || hit.distance >= reach)
    return {inside ? Coast::kInland : Coast::kFarSea, inside};
  BinShore shore;
  // No boundary within the box (with a margin far above rounding): every point lies on the
  // side of the centre.
  if (hit.distance > halfDiagonal * (1.0 + 1e-9) + 1e-6)
    shore.onLand = inside;
  // Every point is within hit.distance + halfDiagonal of the boundary point found, so its
  // nearest segment (if nearer than the shelf's reach) comes that near the box.
  const double near = std::min(hit.distance + halfDiagonal, shelf) * (1.0 + 1e-9) + 1e-6;
  shore.begin = segments.size();
  land.segmentsMeeting(box.expanded(near), segments);
  shore.count = segments.size() - shore.begin;
  return shore;
}

std::vector<double> TileEvaluator::evaluate(const SampleGrid& grid, TileStats* stats) const {
  const construction::WorldData& data = world_.data();
  std::vector<double> heights(grid.points.size());
  if (grid.points.empty())
    return heights;
  const std::vector<std::uint32_t> blocks = blocks_.blocksMeeting(grid.bounds);
  const auto [groups, rows] = binShape(grid);
  TileStats local;
  local.blocks = blocks.size();
  Aabb reach; // holds the support of every primitive gathered
  for (std::uint32_t b : blocks) {
    const construction::BlockPrimitives& r = data.blocks[b];
    reach.add(blocks_.influence(b));
    local.terrainPrimitives += r.terrainEnd - r.terrainBegin;
    local.riverPrimitives += r.riverEnd - r.riverBegin;
  }
  // Kept per thread from tile to tile: a tile then neither allocates nor clears the megabytes
  // of boxes and lists it is about to write. Only up to kKeptScratchSamples samples: a larger
  // grid releases them (a served thread keeps a few megabytes, not those of its largest tile).
  thread_local std::vector<Aabb> runBoxes;
  thread_local Bins bins, riverBins;
  Bins::runBoxes(grid, runBoxes);
  bins.reset(grid, runBoxes, groups, rows, reach, true);
  // Rivers are thin beside a bin: they get bins one row high, so a run searches only the
  // rivers that come near its own row.
  riverBins.reset(grid, runBoxes, groups, 1, reach, false);
  const construction::InstructionSet instructions = construction::instructionSet();
  // Blocks are ascending and their ranges contiguous, so primitive ids arrive ascending.
  for (std::uint32_t b : blocks) {
    const construction::BlockPrimitives& r = data.blocks[b];
    // The block's primitives lie within its influence box: their bins are among its bins,
    // and where that is one bin they all go there (extra candidates are harmless).
    const Bins::Range range = bins.rangeOf(blocks_.influence(b));
    if (range.size() == 1 && bins.monotone())
      for (std::uint32_t i = r.terrainBegin; i < r.terrainEnd; ++i)
        bins.addTerrain(bins.at(range.i0, range.j0), i, terrainDiscs_.keyY[i]);
    else if (range.size() > 0 && range.size() <= kScanBins && bins.monotone())
      bins.addTerrainDiscs(range, terrainDiscs_, r.terrainBegin, r.terrainEnd - r.terrainBegin,
                           instructions);
    else if (range.size() > 0)
      for (std::uint32_t i = r.terrainBegin; i < r.terrainEnd; ++i) {
        const Vec2 center = terrainDiscs_.center(i);
        const double reach2 = terrainDiscs_.reach2[i];
        const Aabb support = Aabb{center, center}.expanded(data.terrain[i].radius);
        if (!bins.monotone()) {
          bins.forEachBin(
              support, [&](const Aabb& box) { return squaredDistanceToBox(center, box) <= reach2; },
              [&](std::size_t bin) { bins.addTerrain(bin, i, terrainDiscs_.keyY[i]); });
          continue;
        }
        bins.addTerrainDisc(bins.rangeOf(support), terrainDiscs_, i);
      }
    for (std::uint32_t i = r.riverBegin; i < r.riverEnd; ++i) {
      // A bin no run of the curve comes within reach of gets w = 0 from this river.
      const auto always = [](const Aabb&) { return true; };
      const std::span<const Aabb> chunks = world_.riverChunks(i);
      const auto all = static_cast<std::uint32_t>(chunks.size());
      const Aabb& support = world_.riverSupport(i);
      const Bins::Range supportBins = riverBins.rangeOf(support);
      // The bins the support meets first: at far zooms most rivers meet one (zoom 5: all;
      // testing each run of theirs against each bin of the range cost zoom 5 a third more).
      std::size_t only = 0, meeting = 0;
      riverBins.forEachBin(supportBins, support, always, [&](std::size_t bin) {
        only = bin;
        ++meeting;
      });
      if (meeting <= 1) { // a short river within one bin (or none): all of its curve
        if (meeting == 1)
          riverBins.addRiverChunks(only, i, 0, all);
        continue;
      }
      const double riverReach = world_.riverReach(i);
      if (riverBins.monotone() && supportBins.size() <= kRangeBins) {
        riverBins.addRiverInRange(supportBins, i, chunks, riverReach);
        continue;
      }
      for (std::uint32_t c = 0; c < all; ++c)
        riverBins.forEachBin(chunks[c].expanded(riverReach), always,
                             [&](std::size_t bin) { riverBins.addRiverChunks(bin, i, c, c + 1); });
    }
  }
  bins.finish();
  riverBins.finish();
  std::vector<BinShore> shores(bins.count());
  std::vector<std::uint32_t> shoreSegments;
  for (int j = 0; j < bins.perColumn(); ++j)
    for (int i = 0; i < bins.perRow(); ++i)
      shores[bins.at(i, j)] = shoreOf(bins.box(i, j), shoreSegments);
  const auto width = static_cast<std::size_t>(grid.width);
  // The run of samples from (row, col) with its spacing, river candidates and heights.
  const auto runAt = [&](int row, int col) {
    const std::size_t k = static_cast<std::size_t>(row) * width + static_cast<std::size_t>(col);
    const std::size_t n =
        std::min(static_cast<std::size_t>(base::kLanes), width - static_cast<std::size_t>(col));
    return construction::World::PointRun{{grid.points.data() + k, n},
                                         grid.rowSpacing[static_cast<std::size_t>(row)],
                                         riverBins.rivers(riverBins.binOf(row, col)),
                                         {heights.data() + k, n}};
  };
  // Where a bin is tall beside a terrain primitive's reach (samples tens of metres apart or
  // more), each run or pair of rows takes only the bin's candidates whose centres lie within
  // World::terrainReach() of its samples in y: the others add exactly nothing, and the list
  // keeps its order, so the sums keep their bits. The lists keep each centre's y beside its
  // id, so this filter reads two arrays in order (in vector code) and not the blend's records.
  // It pays where it keeps well under all of a bin's candidates (about keptFraction of them;
  // measured: −1.8 % at 0.78, zoom 11; +1 % at 0.87, zoom 12).
  const double terrainReach = world_.terrainReach();
  const double rowHeight = grid.bounds.size().y / grid.height;
  const double keptFraction = (2.0 * rowHeight + 2.0 * terrainReach) /
                              (static_cast<double>(rows) * rowHeight + 2.0 * terrainReach);
  const bool byRow = rows >= 4 && keptFraction < 0.85;
  const std::size_t runsPerRow = (width + base::kLanes - 1) / base::kLanes;
  std::vector<std::uint32_t> near(byRow ? kDenseBin + kFilterOverrun : 0);
  for (int row = 0; row < grid.height;) {
    // Two rows of one bin share their terrain candidates: their runs are evaluated in pairs.
    const bool paired = row + 1 < grid.height && bins.binOf(row + 1, 0) == bins.binOf(row, 0);
    for (int col = 0; col < grid.width; col += base::kLanes) {
      const std::size_t bin = bins.binOf(row, col);
      const construction::World::PointRun first = runAt(row, col);
      std::span<const std::uint32_t> terrain = bins.terrain(bin);
      if (byRow && terrain.size() <= kDenseBin) {
        const std::size_t q = static_cast<std::size_t>(col) / base::kLanes;
        Aabb samples = runBoxes[static_cast<std::size_t>(row) * runsPerRow + q];
        if (paired)
          samples.add(runBoxes[static_cast<std::size_t>(row + 1) * runsPerRow + q]);
        const double low = samples.min.y - terrainReach, high = samples.max.y + terrainReach;
        // The keys are the centres' y rounded to float: widened by far more than the rounding
        // of both ends (a relative 2^-24 each), the range keeps every candidate it must.
        const double slack = (std::fabs(low) + std::fabs(high)) * 0x1p-20 + 1e-3;
        const auto lowKey = static_cast<float>(low - slack);
        const auto highKey = static_cast<float>(high + slack);
        const std::size_t n = keepKeysWithin(bins.terrainKeys(bin), terrain.data(), lowKey, highKey,
                                             near.data(), instructions);
        terrain = std::span<const std::uint32_t>(near).first(n);
      }
      if (terrain.size() > kDenseBin) {
        // Samples kilometres apart (low zooms): each point's own cell of the world's index
        // holds far fewer candidates than the bin.
        for (int r = row; r < row + (paired ? 2 : 1); ++r) {
          const construction::World::PointRun run = runAt(r, col);
          for (std::size_t l = 0; l < run.points.size(); ++l)
            run.heights[l] = world_.height(run.points[l], run.spacing);
        }
        continue;
      }
      const BinShore& s = shores[bin];
      const construction::World::Shore shore{
          s.coast, s.onLand,
          std::span<const std::uint32_t>(shoreSegments).subspan(s.begin, s.count)};
      if (paired)
        world_.heightsFrom(first, runAt(row + 1, col), terrain, shore);
      else
        world_.heightsFrom(first.points, first.spacing, terrain, first.rivers, shore,
                           first.heights);
    }
    row += paired ? 2 : 1;
  }
  if (grid.points.size() > kKeptScratchSamples) {
    runBoxes = {};
    bins = Bins{};
    riverBins = Bins{};
  }
  if (stats)
    *stats = local;
  return heights;
}

} // namespace strahler::tiling
