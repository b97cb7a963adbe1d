#pragma once

#include "strahler/geometry/aabb.h"
#include "strahler/geometry/vec2.h"

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

namespace strahler::construction::detail {

/// The nearest point of a channel to some point, as the tributary builder asks for it.
struct ChannelPoint {
  geometry::Vec2 position;   ///< on the channel
  geometry::Vec2 downstream; ///< unit direction of the flow there
  double elevation = 0.0;    ///< water elevation there, m
  double fall = 0.0;         ///< how much the water falls per metre downstream there, >= 0
  double distance = 0.0;     ///< from the point asked about, m
};

/// How far water from p goes to reach q when the ground falls along `downhill` (a unit
/// vector, or zero on flat ground): the distance, up to four times it for a point across the
/// slope and seven times for one uphill, so that heads drain down their slope (pinnate
/// gullies) rather than to whatever channel is nearest.
double linkCost(geometry::Vec2 p, geometry::Vec2 q, geometry::Vec2 downhill) noexcept;

/// What the tributary network reads of its world (World implements it): the smooth control
/// height (the terrain primitives' planes blended, no noise, no rivers), the nearest point of
/// the river graph's channels within a distance, and whether a point lies on land.
class TributarySource {
public:
  virtual ~TributarySource() = default;
  /// The control height at p, m.
  virtual double controlHeight(geometry::Vec2 p) const = 0;
  /// The point of a river channel within `reach` of p that water from p reaches first
  /// (linkCost()), if any.
  virtual bool nearestRiver(geometry::Vec2 p, double reach, geometry::Vec2 downhill,
                            ChannelPoint& out) const = 0;
  /// The height at p before any tributary is carved, for samples `spacing` apart, m.
  virtual double groundHeight(geometry::Vec2 p, double spacing) const = 0;
  /// Whether p lies on land.
  virtual bool onLand(geometry::Vec2 p) const = 0;
};

/// Drainage below the river graph's scale (issue 25): levels of procedural tributaries, cells
/// of kLevelCell[k] metres, one jittered head per cell; each head joins the nearest channel of
/// a coarser level (the graph's rivers for level 0) along a curve that leaves the head along
/// its chord and meets the parent along the parent's flow (acute confluences). The channel's
/// water rises from the parent's at the junction to the control height at the head along
/// (ℓ / L)², so it is monotone and its incision tapers to nothing at both ends. A channel
/// carves a V-shaped valley z(ℓ) + S (√(d² + b²) − b) into the ground wherever that is lower,
/// within a support that fades it out; finer levels carve into the result of coarser ones.
/// Every curve is a pure function of its cell and of the world, built per region of cells and
/// kept per thread, so any evaluation order gives the same bits.
class Tributaries {
public:
  static constexpr int kLevels = 3;
  static constexpr std::array<double, kLevels> kLevelCell{400.0, 200.0, 100.0}; ///< m
  static constexpr int kRegionCells = 16;
  static constexpr int kCurvePoints = 7;

  /// A network of the world `seed` with `levels` levels (1 to kLevels), coarsest first.
  Tributaries(std::uint64_t seed, int levels);

  /// The height `h` at p (on land) with the tributaries' valleys carved, for samples `spacing`
  /// apart (a level fades out like a noise octave of its cell's wavelength).
  double carve(const TributarySource& world, geometry::Vec2 p, double h, double spacing) const;

  /// One tributary channel: points from its head to its junction, and water elevations there.
  struct Curve {
    std::array<geometry::Vec2, kCurvePoints> points{};
    std::array<double, kCurvePoints> water{};
    geometry::Aabb box;     ///< of the points, grown by the support radius
    double support = 0.0;   ///< m from the channel where its carving has faded out
    double sideSlope = 0.0; ///< of its valley's sides, m/m
  };
  /// The curves of one level in a region of kRegionCells² cells (with the halo of cells whose
  /// curves reach it), and per cell of the region the curves whose support meets it.
  struct Region {
    std::vector<Curve> curves;
    std::vector<std::uint32_t> cellStart; ///< kRegionCells² + 1 offsets into cellCurves
    std::vector<std::uint32_t> cellCurves;
  };

  /// The region (level, rx, ry), built on first use in this thread.
  std::shared_ptr<const Region> region(const TributarySource& world, int level, std::int64_t rx,
                                       std::int64_t ry) const;
  /// The channel point of any level coarser than `level` (rivers included) within `reach` of
  /// p of least linkCost() along `downhill`.
  bool nearestCoarser(const TributarySource& world, int level, geometry::Vec2 p, double reach,
                      geometry::Vec2 downhill, ChannelPoint& out) const;

private:
  /// carve() for one level.
  double carveLevel(const TributarySource& world, int level, geometry::Vec2 p, double h,
                    double spacing) const;
  std::shared_ptr<const Region> build(const TributarySource& world, int level, std::int64_t rx,
                                      std::int64_t ry) const;

  std::uint64_t seed_;
  int levels_;
  std::uint64_t serial_; // tells this network's regions from another world's in a thread's cache
};

} // namespace strahler::construction::detail
