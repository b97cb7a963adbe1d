#pragma once

#include "strahler/base/strong_id.h"
#include "strahler/construction/operators.h"
#include "strahler/construction/tectonic_plates.h"
#include "strahler/construction/world_data.h"
#include "strahler/geometry/grid_index.h"
#include "strahler/geometry/polygon_index.h"
#include "strahler/noise/lattice_noise.h"
#include "strahler/simd/instruction_set.h"

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>

namespace strahler::construction {

namespace detail {
class Folds;
class ReliefField;
class Tributaries;
class WorldTributarySource;
} // namespace detail

/// How the relief meets the sea: a beach ramp on land and a smooth shelf below sea level.
struct CoastShape {
  static constexpr double kBand = 400.0;        ///< m inland over which the coast ramp acts.
  static constexpr double kBeachSlope = 0.02;   ///< Slope of the beach ramp, m/m.
  static constexpr double kShelfDepth = 120.0;  ///< Depth the shelf tends to, m.
  static constexpr double kShelfWidth = 3000.0; ///< e-folding distance of the shelf, m.
  /// Distance from the shore beyond which the sea floor is taken as flat, m.
  static constexpr double kShelfReach = 4.0 * kShelfWidth;
};

/// The noise octaves every world shares: wavelength kLongest / 2^k for k < kOctaves.
struct NoiseOctaves {
  static constexpr double kLongest = 2048.0; ///< m
  static constexpr int kOctaves = 12;        ///< down to 1 m
};

/// A world ready to evaluate: the data plus the indexes that make h(p) local.
/// h = C(B(T…), U(R…)) (Section 6) on land, shaped by CoastShape at the shore and below
/// the sea, plus the erosion's residual (WorldData::relief, smoothly interpolated) off the
/// rivers' floors. Evaluation is a pure, thread-safe function of (world, point, sample spacing).
/// The terrain blend B(T…) = Σ w_i h_i(p) / Σ w_i + Σ_k A G^k octave_k(p), h_i the plane of
/// primitive i (its elevation and slope), where the amplitude A
/// and gain G are the w-weighted means of the primitives' amplitude and roughness, and octaves
/// 2–6 are gullies running down the blend's gradient (gradient noise on an eroded world, whose
/// residual carries that drainage): one shared relief whose character follows the primitives
/// (see docs/architecture.md). With drawn mountains
/// (data().features.mountains) B(T…) also holds the tectonic folds (TectonicPlates), added
/// before the rivers' union.
class World {
public:
  /// Indexes `data` (which must be consistent, as the generator and the store make it).
  explicit World(WorldData data);

  /// The vector description.
  const WorldData& data() const noexcept { return data_; }
  /// Bounding box of river primitive i's support (i indexes data().rivers).
  const geometry::Aabb& riverSupport(base::PrimitiveId i) const noexcept {
    return hotRivers_[i.index()].support;
  }
  /// Boxes of the runs of 8 segments of river primitive i's curve.
  std::span<const geometry::Aabb> riverChunks(base::PrimitiveId i) const noexcept {
    const HotRiver& r = hotRivers_[i.index()];
    return {chunkBoxes_.data() + r.chunkBegin, r.chunkCount};
  }
  /// How near (m) a run of river primitive i's curve must come to a point to shape it: the
  /// river's radius with a margin for rounding (extra runs are harmless, missing ones not).
  double riverReach(base::PrimitiveId i) const noexcept;
  /// How far (m) in y a terrain primitive's centre may lie from a point it shapes: the
  /// largest radius with a margin above rounding (a primitive farther adds exactly nothing).
  double terrainReach() const noexcept { return terrainReach_; }
  /// A river primitive among the candidates of some points, with the runs of its curve
  /// (riverChunks()) to search: [firstChunk, endChunk) must hold every run that comes within
  /// riverReach() of any of the points.
  struct RiverCandidate {
    std::uint32_t id = 0;
    std::uint32_t firstChunk = 0;
    std::uint32_t endChunk = 0;
  };
  /// River primitive i with every run of its curve.
  RiverCandidate wholeRiver(base::PrimitiveId i) const noexcept {
    return {i.value, 0, hotRivers_[i.index()].chunkCount};
  }
  /// The plates of the drawn mountains (data().features.mountains), null without any.
  const TectonicPlates* plates() const noexcept;
  /// The tectonic folds' strength at p in [0, 1]: 0 without drawn mountains, on plate
  /// boundaries and beyond the folds' reach from convergent ones.
  double foldStrength(geometry::Vec2 p) const noexcept;
  /// The land with fast point and distance queries.
  const geometry::PolygonIndex& land() const noexcept { return land_; }

  /// Every stage of the evaluation at one point, for tests and inspection.
  struct Evaluation {
    Sample terrain;      ///< B(T…): blend of the terrain primitives (w = 0: none covers p).
    Sample rivers;       ///< U(R…): union of the river primitives (w = 0: none covers p).
    double tree = 0.0;   ///< h of C(B(T…), U(R…)) before the coast shaping.
    double height = 0.0; ///< Final elevation after the coast shaping, m.
  };

  /// Elevation (m) at local point p for samples `spacing` metres apart: noise octaves shorter
  /// than twice the spacing are faded out (fully present from four times the spacing).
  double height(geometry::Vec2 p, double spacing) const noexcept {
    return evaluate(p, spacing).height;
  }
  /// height(points[i], spacing) into heights[i] for every i, base::kLanes neighbouring points
  /// at a time where they share their cell of the world's index (rows of a raster).
  void heights(std::span<const geometry::Vec2> points, double spacing,
               std::span<double> heights) const noexcept;
  /// The full evaluation at p (see height()).
  Evaluation evaluate(geometry::Vec2 p, double spacing) const noexcept;

  /// What a caller knows about where p lies, to skip work that cannot change the result.
  enum class Coast {
    kUnknown, ///< Measure the distance to the shore.
    kInland,  ///< p is on land and at least CoastShape::kBand from any shore.
    kFarSea,  ///< p is off the land and at least shelfReach() from any shore.
  };

  /// Distance from the shore beyond which the sea floor is flat, m.
  static double shelfReach() noexcept;
  /// What a caller knows about the shore near a group of points (heightsFrom()).
  struct Shore {
    Coast coast = Coast::kUnknown;
    /// With kUnknown: whether every point lies on land (true) or every point at sea (false).
    std::optional<bool> onLand;
    /// With kUnknown: indices into land().segments() that hold the nearest boundary segment of
    /// every point nearer than shelfReach() to the boundary (otherwise the index is searched).
    std::optional<std::span<const std::uint32_t>> segments;
  };

  /// The evaluation at p from explicit candidate primitives: `terrain` holds indices into
  /// data().terrain, `rivers` candidates of data().rivers, both ascending, and must include
  /// every primitive whose support contains p (others are harmless). Bit-identical to
  /// evaluate(p, spacing).
  Evaluation evaluateFrom(geometry::Vec2 p, double spacing, std::span<const std::uint32_t> terrain,
                          std::span<const RiverCandidate> rivers,
                          Coast coast = Coast::kUnknown) const noexcept;

  /// Heights at many points sharing one spacing and one candidate set (as evaluateFrom() asks
  /// of each point), base::kLanes at a time with vector instructions: heights[i] equals
  /// height(points[i], spacing) bit for bit. `heights` has points.size() elements.
  void heightsFrom(std::span<const geometry::Vec2> points, double spacing,
                   std::span<const std::uint32_t> terrain, std::span<const RiverCandidate> rivers,
                   const Shore& shore, std::span<double> heights) const noexcept;

  /// One run of points for heightsFrom(): at most base::kLanes points sharing a spacing,
  /// their river candidates (as heightsFrom() asks) and where their heights go
  /// (points.size() elements).
  struct PointRun {
    std::span<const geometry::Vec2> points;
    double spacing = 0.0;
    std::span<const RiverCandidate> rivers;
    std::span<double> heights;
  };
  /// heightsFrom() for two runs that share the terrain candidates and the shore (two rows of a
  /// tile's bin): runs of base::kLanes points get their terrain sums in one pass (more work in
  /// flight per candidate); the same bits as one call per run.
  void heightsFrom(const PointRun& first, const PointRun& second,
                   std::span<const std::uint32_t> terrain, const Shore& shore) const noexcept;

  /// The fields of a terrain primitive the blend reads, packed (56 bytes).
  struct HotTerrain {
    geometry::Vec2 center;
    double radius2 = 0.0;        ///< r²
    double inverseRadius2 = 0.0; ///< 1 / r² (0 for r = 0)
    double elevation = 0.0;      ///< c_z
    geometry::Vec2 slope;        ///< the plane's gradient
    double amplitude = 0.0;      ///< ≥ 0
    double roughness = 0.0;      ///< fBm gain in [0, kMaxRoughness]
  };
  /// A segment of a river curve as the closest-point search reads it (40 bytes: the search
  /// streams them).
  struct HotSegment {
    geometry::Vec2 a;            ///< start
    geometry::Vec2 ab;           ///< end − start
    double inverseLength2 = 0.0; ///< 1 / |ab|² (0 for a segment of length 0)
  };
  /// What evaluation reads of a river primitive: the closest-point search's fields in one
  /// cache line, its profile's in the next.
  struct alignas(64) HotRiver {
    geometry::Aabb support;                           ///< the support's box
    double radius = 0.0;                              ///< r
    double reach = 0.0;                               ///< riverReach()
    std::uint32_t segmentBegin = 0, segmentCount = 0; ///< its segments, river after river
    std::uint32_t chunkBegin = 0, chunkCount = 0;     ///< its runs' boxes, river after river
    alignas(64) double widthUp = 0.0;                 ///< channel width upstream, m
    double widthDown = 0.0;                           ///< ... and downstream
    double depthUp = 0.0;                             ///< channel depth upstream, m
    double depthDown = 0.0;                           ///< ... and downstream
    double bankSlope = 0.0;                           ///< primitives::bankSlope() of its type
    double minReach = 0.0; ///< primitives::valleyMinReach(), at most the radius
    bool flatBed = false;  ///< primitives::hasFlatBed() of its type
  };
  /// Largest fBm gain evaluated (keeps octave amplitudes decreasing).
  static constexpr double kMaxRoughness = 0.95;

private:
  friend class detail::WorldTributarySource;
  /// The terrain primitives' planes blended at p, without noise or rivers (0 where none
  /// covers p): the smooth height the tributaries are routed over.
  double controlHeight(geometry::Vec2 p) const noexcept;
  /// The height at p before the tributaries are carved.
  double uncarvedHeight(geometry::Vec2 p, double spacing) const noexcept;
  /// The height `h` at p with the tributaries' valleys carved (p on land, h > 0).
  double carveTributaries(geometry::Vec2 p, double h, double spacing) const;
  /// carveTributaries() over a group's heights, in place (nothing without tributaries).
  void carveGroup(const geometry::Vec2* group, double spacing, std::span<double> heights) const;
  /// B(T…) at `lanes` points into h, w: 1 (scalar code, at first[0]) or base::kLanes (vector
  /// code) at `first` and, if not null, base::kLanes more at `second` (their results follow
  /// the first's), samples spacing[0] and spacing[1] apart; the same bits either way.
  void terrainLanes(std::size_t lanes, const geometry::Vec2* first, const geometry::Vec2* second,
                    std::array<double, 2> spacing, std::span<const std::uint32_t> ids, double* h,
                    double* w) const noexcept;
  /// U(R…) at `lanes` points into riverH and riverW [0 .. lanes): 1 or base::kLanes, as
  /// terrainLanes, samples `spacing` apart (their channels' floors: primitives::riverFloor),
  /// over the terrain blend's heights `terrain` there (the union keeps the deeper cut).
  void riversLanes(std::size_t lanes, const geometry::Vec2* points, double spacing,
                   const double* terrain, std::span<const RiverCandidate> rivers, double* riverH,
                   double* riverW) const noexcept;
  /// The rivers, the shore and the height at base::kLanes points `group` `spacing` apart
  /// (heights.size() of them are kept) from their terrain blend h, w.
  void finishGroup(const geometry::Vec2* group, double spacing, const double* h, const double* w,
                   std::span<const RiverCandidate> rivers, const Shore& shore,
                   std::span<double> heights) const noexcept;
  /// Adds the erosion's residual (data().relief, smoothly interpolated) to heights[l] at
  /// group[l] for samples `spacing` apart, except on a river's floor (riverW[l] = 1), which
  /// keeps its line and depth; nothing without a residual.
  void addRelief(const geometry::Vec2* group, double spacing, const double* riverW,
                 std::span<double> heights) const noexcept;
  /// Whether each of base::kLanes points `group` lies on land (1) or not (0): land().contains()
  /// in vector code where they share a ray band.
  void insideLand(const geometry::Vec2* group, double* onLand) const noexcept;
  /// The height at a point `onLand` or not, `shore` metres from the boundary (capped at
  /// CoastShape::kBand on land and shelfReach() at sea), from its terrain and rivers.
  static double shapeCoast(const Sample& terrain, const Sample& rivers, bool onLand,
                           double shore) noexcept;
  /// The height at p where the shore is `coast`.
  double shapeCoast(geometry::Vec2 p, const Sample& terrain, const Sample& rivers,
                    Coast coast) const noexcept;

  WorldData data_;
  geometry::PolygonIndex land_;
  geometry::GridIndex terrainGrid_;
  geometry::GridIndex riverGrid_;
  // Per cell of riverGrid_: its rivers, with the runs of their curves that come near the cell.
  std::vector<std::vector<RiverCandidate>> riverCells_;
  std::vector<HotRiver> hotRivers_; // per river primitive
  // The box of each run of 8 curve segments, so the closest-point search skips whole runs far
  // from p instead of testing every segment's box.
  std::vector<geometry::Aabb> chunkBoxes_;
  std::vector<HotSegment> hotSegments_; // the segments of every river curve
  // Per segment of hotSegments_, its water surface (read where it is a point's nearest): the
  // water elevation at its start, then its rise to its end.
  std::vector<double> water_;
  std::vector<HotTerrain> hot_; // per terrain primitive
  double terrainReach_ = 0.0;
  noise::LatticeNoise noise_;
  std::uint32_t gullySeed_ = 0;                            // shuffles the gully octaves' phases
  std::shared_ptr<const detail::Tributaries> tributaries_; // drainage below the graph's scale
  std::shared_ptr<const detail::Folds> folds_; // tectonic folds; null without drawn mountains
  std::shared_ptr<const detail::ReliefField> relief_; // the erosion's residual; null: none
};

// The instruction set evaluation runs on lives in strahler/simd/instruction_set.h; these names
// stay for code that still says construction:: (core/tiling: tile_evaluator.cpp, bins.h,
// bins_test.cpp).
using simd::InstructionSet;
using simd::instructionSet;
using simd::useInstructionSet;

/// Fade of a noise octave of wavelength `wavelength` at sample spacing `spacing`: 0 below
/// twice the spacing, 1 from four times, linear between.
double octaveFade(double wavelength, double spacing) noexcept;

} // namespace strahler::construction
