#include "strahler/tiling/tile_evaluator.h"

#include "bins.h"

#include "strahler/base/lanes.h"
#include "strahler/base/strong_id.h"
#include "strahler/tiling/candidate_filters.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <utility>
#include <vector>

namespace strahler::tiling {
namespace {

using geometry::Aabb;
using geometry::Vec2;

/// Distance from p to box b (0 inside).
double distanceToBox(Vec2 p, const Aabb& b) {
  const Vec2 gap = gapsToBox(p, b);
  return std::hypot(gap.x, gap.y);
}

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

using construction::World;

/// What the points of a bin share about the shore; its candidate segments are given as
/// offsets into a list shared by all bins (filled before any is read): begin and count.
struct BinShore {
  World::Coast coast = World::Coast::kUnknown;
  std::optional<bool> onLand;
  std::size_t begin = 0, count = 0; ///< candidate segments: segments[begin, begin + count)
};

/// The shore of every bin: per bin, what its points share, and the segments all bins name.
struct Shores {
  std::vector<BinShore> bins;
  std::vector<std::uint32_t> segments;
};

/// The blocks meeting a tile, the box their primitives reach and what the tile touched.
struct Gathered {
  std::vector<base::BlockId> blocks; ///< ascending
  Aabb reach;                        ///< holds the support of every primitive gathered
  TileStats stats;
};

/// A tile's per-thread scratch, kept from tile to tile: a tile then neither allocates nor
/// clears the megabytes of boxes and lists it is about to write.
struct Scratch {
  std::vector<Aabb> runBoxes; ///< Bins::runBoxes() of the grid
  Bins bins;                  ///< terrain candidates
  Bins riverBins;             ///< river candidates, in bins one row high
};

/// Gathers the blocks whose influence box meets `bounds`, with their reach and counts.
Gathered gatherBlocks(const BlockIndex& index, const construction::WorldData& data,
                      const Aabb& bounds) {
  Gathered g;
  g.blocks = index.blocksMeeting(bounds);
  g.stats.blocks = g.blocks.size();
  for (const base::BlockId b : g.blocks) {
    const construction::BlockPrimitives& r = data.blocks[b.index()];
    g.reach.add(index.influence(b));
    g.stats.terrainPrimitives += r.terrainEnd - r.terrainBegin;
    g.stats.riverPrimitives += r.riverEnd - r.riverBegin;
  }
  return g;
}

/// Makes the scratch's bins those of `grid` (of `groups` runs by `rows` rows), empty.
void resetBins(const SampleGrid& grid, int groups, int rows, const Aabb& reach, Scratch& scratch) {
  Bins::runBoxes(grid, scratch.runBoxes);
  scratch.bins.reset(grid, scratch.runBoxes, groups, rows, reach, true);
  // Rivers are thin beside a bin: they get bins one row high, so a run searches only the
  // rivers that come near its own row.
  scratch.riverBins.reset(grid, scratch.runBoxes, groups, 1, reach, false);
}

/// Adds the terrain primitives of one block (`r`, within box `influence`) to the bins their
/// discs meet.
void binTerrain(const construction::BlockPrimitives& r, const Aabb& influence,
                const construction::WorldData& data, const TerrainDiscs& discs,
                construction::InstructionSet instructions, Bins& bins) {
  // The block's primitives lie within its influence box: their bins are among its bins,
  // and where that is one bin they all go there (extra candidates are harmless).
  const Bins::Range range = bins.rangeOf(influence);
  if (range.size() == 1 && bins.monotone())
    for (std::uint32_t i = r.terrainBegin; i < r.terrainEnd; ++i)
      bins.addTerrain(bins.at(range.i0, range.j0), i, discs.keyY[i]);
  else if (range.size() > 0 && range.size() <= kScanBins && bins.monotone())
    bins.addTerrainDiscs(range, discs, r.terrainBegin, r.terrainEnd - r.terrainBegin, instructions);
  else if (range.size() > 0)
    for (std::uint32_t i = r.terrainBegin; i < r.terrainEnd; ++i) {
      const Vec2 center = discs.center(i);
      const double reach2 = discs.reach2[i];
      const Aabb support = Aabb{center, center}.expanded(data.terrain[i].radius);
      if (!bins.monotone()) {
        bins.forEachBin(
            support, [&](const Aabb& box) { return squaredDistanceToBox(center, box) <= reach2; },
            [&](std::size_t bin) { bins.addTerrain(bin, i, discs.keyY[i]); });
        continue;
      }
      bins.addTerrainDisc(bins.rangeOf(support), discs, i);
    }
}

/// Adds river primitive `river` to the river bins a run of its curve comes near.
void binRiver(const World& world, base::PrimitiveId river, Bins& riverBins) {
  const std::uint32_t i = river.value;
  // A bin no run of the curve comes within reach of gets w = 0 from this river.
  const auto always = [](const Aabb&) { return true; };
  const std::span<const Aabb> chunks = world.riverChunks(river);
  const auto all = static_cast<std::uint32_t>(chunks.size());
  const Aabb& support = world.riverSupport(river);
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
    return;
  }
  const double riverReach = world.riverReach(river);
  if (riverBins.monotone() && supportBins.size() <= kRangeBins) {
    riverBins.addRiverInRange(supportBins, i, chunks, riverReach);
    return;
  }
  for (std::uint32_t c = 0; c < all; ++c)
    riverBins.forEachBin(chunks[c].expanded(riverReach), always,
                         [&](std::size_t bin) { riverBins.addRiverChunks(bin, i, c, c + 1); });
}

/// What the points of `box` share about the shore of `land`; the candidate segments it names
/// are appended to `segments`.
BinShore shoreOf(const geometry::PolygonIndex& land, const Aabb& box,
                 std::vector<std::uint32_t>& segments) {
  using Coast = World::Coast;
  const Vec2 center = box.center();
  const double halfDiagonal = 0.5 * length(box.size());
  const double shelf = World::shelfReach();
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

/// Classifies the shore of every bin (shoreOf()).
Shores classifyShores(const geometry::PolygonIndex& land, const Bins& bins) {
  Shores shores;
  shores.bins.resize(bins.count());
  for (int j = 0; j < bins.perColumn(); ++j)
    for (int i = 0; i < bins.perRow(); ++i)
      shores.bins[bins.at(i, j)] = shoreOf(land, bins.box(i, j), shores.segments);
  return shores;
}

/// The last step: every run of base::kLanes samples of a row evaluated by the world's kernels
/// from its bins' candidates (two rows of a bin at a time), into the heights.
class RunEvaluator {
public:
  /// Runs of `grid` (binned in `scratch`, bins `rows` rows high) into `heights`.
  RunEvaluator(const World& world, const SampleGrid& grid, const Scratch& scratch,
               const Shores& shores, int rows, construction::InstructionSet instructions,
               std::span<double> heights)
      : world_(world), grid_(grid), scratch_(scratch), shores_(shores), instructions_(instructions),
        heights_(heights), width_(static_cast<std::size_t>(grid.width)),
        runsPerRow_((width_ + base::kLanes - 1) / base::kLanes),
        terrainReach_(world.terrainReach()) {
    // Where a bin is tall beside a terrain primitive's reach (samples tens of metres apart or
    // more), each run or pair of rows takes only the bin's candidates whose centres lie
    // within World::terrainReach() of its samples in y: the others add exactly nothing, and
    // the list keeps its order, so the sums keep their bits. The lists keep each centre's y
    // beside its id, so this filter reads two arrays in order (in vector code) and not the
    // blend's records. It pays where it keeps well under all of a bin's candidates (about
    // keptFraction of them; measured: −1.8 % at 0.78, zoom 11; +1 % at 0.87, zoom 12).
    const double rowHeight = grid.bounds.size().y / grid.height;
    const double keptFraction = (2.0 * rowHeight + 2.0 * terrainReach_) /
                                (static_cast<double>(rows) * rowHeight + 2.0 * terrainReach_);
    byRow_ = rows >= 4 && keptFraction < 0.85;
    near_.resize(byRow_ ? kDenseBin + kFilterOverrun : 0);
  }

  /// Evaluates every run of the grid.
  void evaluateAll() {
    const Bins& bins = scratch_.bins;
    for (int row = 0; row < grid_.height;) {
      // Two rows of one bin share their terrain candidates: their runs are evaluated in pairs.
      const bool paired = row + 1 < grid_.height && bins.binOf(row + 1, 0) == bins.binOf(row, 0);
      for (int col = 0; col < grid_.width; col += base::kLanes)
        evaluateRun(row, col, paired);
      row += paired ? 2 : 1;
    }
  }

private:
  /// Evaluates the run at (row, col), and the one below it if `paired`.
  void evaluateRun(int row, int col, bool paired) {
    const std::size_t bin = scratch_.bins.binOf(row, col);
    const std::span<const std::uint32_t> terrain = terrainNear(row, col, paired, bin);
    if (terrain.size() > kDenseBin) {
      evaluatePointByPoint(row, col, paired);
      return;
    }
    const BinShore& s = shores_.bins[bin];
    const World::Shore shore{
        s.coast, s.onLand,
        std::span<const std::uint32_t>(shores_.segments).subspan(s.begin, s.count)};
    const World::PointRun first = runAt(row, col);
    if (paired)
      world_.heightsFrom(first, runAt(row + 1, col), terrain, shore);
    else
      world_.heightsFrom(first.points, first.spacing, terrain, first.rivers, shore, first.heights);
  }

  /// The terrain candidates of `bin` for the run at (row, col) (and the one below if
  /// `paired`): those whose centres lie within reach in y where filtering pays, else all.
  std::span<const std::uint32_t> terrainNear(int row, int col, bool paired, std::size_t bin) {
    const std::span<const std::uint32_t> terrain = scratch_.bins.terrain(bin);
    if (!byRow_ || terrain.size() > kDenseBin)
      return terrain;
    const std::size_t q = static_cast<std::size_t>(col) / base::kLanes;
    Aabb samples = scratch_.runBoxes[static_cast<std::size_t>(row) * runsPerRow_ + q];
    if (paired)
      samples.add(scratch_.runBoxes[static_cast<std::size_t>(row + 1) * runsPerRow_ + q]);
    const double low = samples.min.y - terrainReach_, high = samples.max.y + terrainReach_;
    // The keys are the centres' y rounded to float: widened by far more than the rounding
    // of both ends (a relative 2^-24 each), the range keeps every candidate it must.
    const double slack = (std::fabs(low) + std::fabs(high)) * 0x1p-20 + 1e-3;
    const auto lowKey = static_cast<float>(low - slack);
    const auto highKey = static_cast<float>(high + slack);
    const std::size_t n = keepKeysWithin(scratch_.bins.terrainKeys(bin), terrain.data(), lowKey,
                                         highKey, near_.data(), instructions_);
    return std::span<const std::uint32_t>(near_).first(n);
  }

  /// Evaluates the run at (row, col) (and the one below if `paired`) point by point through
  /// the world's index: samples kilometres apart (low zooms), where each point's own cell of
  /// the index holds far fewer candidates than the bin.
  void evaluatePointByPoint(int row, int col, bool paired) const {
    for (int r = row; r < row + (paired ? 2 : 1); ++r) {
      const World::PointRun run = runAt(r, col);
      for (std::size_t l = 0; l < run.points.size(); ++l)
        run.heights[l] = world_.height(run.points[l], run.spacing);
    }
  }

  /// The run of samples from (row, col) with its spacing, river candidates and heights.
  World::PointRun runAt(int row, int col) const {
    const std::size_t k = static_cast<std::size_t>(row) * width_ + static_cast<std::size_t>(col);
    const std::size_t n =
        std::min(static_cast<std::size_t>(base::kLanes), width_ - static_cast<std::size_t>(col));
    return {{grid_.points.data() + k, n},
            grid_.rowSpacing[static_cast<std::size_t>(row)],
            scratch_.riverBins.rivers(scratch_.riverBins.binOf(row, col)),
            {heights_.data() + k, n}};
  }

  const World& world_;
  const SampleGrid& grid_;
  const Scratch& scratch_;
  const Shores& shores_;
  construction::InstructionSet instructions_;
  std::span<double> heights_;
  std::size_t width_, runsPerRow_;
  double terrainReach_;
  bool byRow_ = false;
  std::vector<std::uint32_t> near_; // terrainNear()'s kept candidates
};

/// The calling thread's scratch.
Scratch& threadScratch() {
  thread_local Scratch scratch;
  return scratch;
}

/// Releases the scratch after a grid of more than kKeptScratchSamples samples: a served thread
/// keeps a few megabytes, not those of its largest tile.
void releaseLargeScratch(const SampleGrid& grid, Scratch& scratch) {
  if (grid.points.size() > kKeptScratchSamples)
    scratch = Scratch{};
}

} // namespace

TileEvaluator::TileEvaluator(const construction::World& world)
    : world_(world), blocks_(world.data()), terrainDiscs_(world.data().terrain) {}

std::vector<double> TileEvaluator::evaluate(const SampleGrid& grid, TileStats* stats) const {
  const construction::WorldData& data = world_.data();
  std::vector<double> heights(grid.points.size());
  if (grid.points.empty())
    return heights;
  const Gathered gathered = gatherBlocks(blocks_, data, grid.bounds);
  Scratch& scratch = threadScratch();
  const auto [groups, rows] = binShape(grid);
  resetBins(grid, groups, rows, gathered.reach, scratch);
  const construction::InstructionSet instructions = construction::instructionSet();
  // Blocks are ascending and their ranges contiguous, so primitive ids arrive ascending.
  for (const base::BlockId b : gathered.blocks) {
    const construction::BlockPrimitives& r = data.blocks[b.index()];
    binTerrain(r, blocks_.influence(b), data, terrainDiscs_, instructions, scratch.bins);
    for (std::uint32_t i = r.riverBegin; i < r.riverEnd; ++i)
      binRiver(world_, base::PrimitiveId(i), scratch.riverBins);
  }
  scratch.bins.finish();
  scratch.riverBins.finish();
  const Shores shores = classifyShores(world_.land(), scratch.bins);
  RunEvaluator(world_, grid, scratch, shores, rows, instructions, heights).evaluateAll();
  releaseLargeScratch(grid, scratch);
  if (stats)
    *stats = gathered.stats;
  return heights;
}

} // namespace strahler::tiling
