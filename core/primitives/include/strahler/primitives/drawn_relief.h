#pragma once

#include "strahler/analysis/hydrology.h"
#include "strahler/input/world_spec.h"
#include "strahler/network/relief_law.h"
#include "strahler/primitives/terrain_primitive.h"

#include <span>
#include <vector>

namespace strahler::primitives {

/// Drop of a drawn ridgeline's crest per metre away from the line (its flanks), m/m.
inline constexpr double kCrestFlank = 0.3;
/// Distance from a river over which a crest's lift fades in, m: the terrain beside a river
/// stays at the river's height, so rivers keep below their banks.
inline constexpr double kCrestRiverClearance = 400.0;

/// What the artist's drawn ridgelines do to the terrain primitives (docs/architecture.md,
/// "Vector map: mountains and ridgelines"). Along each ridge a crest height Z(s) is set every
/// 100 m of its length: its `elevation` when given, else the highest ridge elevation of the
/// analysis (Voronoi vertices) within 1.5 km, smoothed over ±1 km so the crest is continuous.
/// A primitive at distance d < W (the ridge's half-width) is raised to the tent Z − kCrestFlank
/// d, its plane turned down the tent, the lift fading in with the distance to its river and out
/// towards W.
class DrawnRidges {
public:
  /// Crests of spec.features' ridges over `hydrology`; `law` and both must outlive this.
  DrawnRidges(const input::WorldSpec& spec, const analysis::Hydrology& hydrology,
              const network::ReliefLaw& law);

  /// True when no ridge was drawn.
  bool empty() const noexcept { return crests_.empty(); }
  /// Raises `elevation` and turns `slope` (the primitive's unquantised plane) at centre c whose
  /// nearest river point is `riverDistance` away; scales the noise amplitude down on the crest.
  void lift(geometry::Vec2 c, double riverDistance, double& elevation, geometry::Vec2& slope,
            double& amplitude) const noexcept;
  /// Crest height (m) of ridge i at the point of its line nearest to p.
  double crestAt(std::size_t i, geometry::Vec2 p) const noexcept;

private:
  struct Crest {
    std::vector<geometry::Vec2> line;
    std::vector<double> along;  ///< Arc length at each vertex of `line`, m.
    std::vector<double> height; ///< Z every kCrestStep of arc length.
    double halfWidth = 0.0;
  };
  std::vector<Crest> crests_;
};

/// Radii (m) of spec.features' mountains (network::mountainRadius), in order.
std::vector<double> mountainRadii(const input::WorldSpec& spec);
/// Gain of the drawn mountains at p: 1 + Σ_m (gains[m] − 1) · smoothstep(1 − d_m / radii[m]),
/// d_m the distance to mountain m: each scales the relief around it, most at its summit.
double mountainGain(const input::Features& features, std::span<const double> radii,
                    std::span<const double> gains, geometry::Vec2 p) noexcept;
/// t with its relief above `base` (the river height it rises from) scaled by `gain` ≥ 0:
/// elevation base + gain (elevation − base), plane and noise amplitude times gain; quantised.
TerrainPrimitive scaleRelief(const TerrainPrimitive& t, double base, double gain) noexcept;

} // namespace strahler::primitives
