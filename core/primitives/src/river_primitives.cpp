#include "strahler/primitives/river_primitives.h"

#include "strahler/base/random.h"
#include "strahler/geometry/aabb.h"
#include "strahler/geometry/distance.h"
#include "strahler/network/drawn_rivers.h"
#include "strahler/primitives/meander_curve.h"
#include "strahler/primitives/quantization.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <numbers>
#include <optional>
#include <utility>

namespace strahler::primitives {
namespace {

using geometry::Vec2;

constexpr double kPi = std::numbers::pi;
constexpr std::uint64_t kRiverStream = 0x7269766572ull;
constexpr std::uint64_t kWanderStream = 0x77616e646572ull; // rivers wandering under the tributaries
constexpr double kMinMeanderWavelength = 200.0;            // m: keeps curves within the file budget
/// Share of δ a river's curve keeps from Γ (keepClearOfShore): 150 m by default, where the
/// coast's cap (World::CoastShape) allows a bed about 160 m up.
constexpr double kShoreClearance = 0.5;

/// The inflow of `node` that continues straight through it: highest Strahler number, then
/// highest flow, then lowest id. Invalid for a leaf.
network::NodeId mainInflow(const network::RiverNetwork& net, const analysis::NetworkAnalysis& a,
                           network::NodeId node) {
  network::NodeId best;
  for (network::NodeId c : net.node(node).children) {
    if (!best.valid()) {
      best = c;
      continue;
    }
    const auto& nc = net.node(c);
    const auto& nb = net.node(best);
    if (nc.strahler > nb.strahler ||
        (nc.strahler == nb.strahler && a.flow[c.index()] > a.flow[best.index()]))
      best = c;
  }
  return best;
}

Vec2 rotate(Vec2 v, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * v.x - s * v.y, s * v.x + c * v.y};
}

/// The unit direction of the river through `id` toward its parent, the tangent every curve at
/// the node shares with it: the centripetal Catmull-Rom tangent through the main inflow, the
/// node and its parent (so a chain of edges, as the DLA grower's, runs through its nodes as one
/// smooth spline); the edge's chord at a source; the main inflow's chord at a confluence and at
/// a mouth.
Vec2 throughTangent(const network::RiverNetwork& net, const analysis::NetworkAnalysis& a,
                    network::NodeId id) {
  const network::RiverNode& node = net.node(id);
  const network::NodeId up = mainInflow(net, a, id);
  const Vec2 p1 = node.position;
  if (!node.parent.valid())
    return up.valid() ? normalize(p1 - net.node(up).position) : Vec2{1.0, 0.0};
  const Vec2 p2 = net.node(node.parent).position;
  if (!up.valid())
    return normalize(p2 - p1);
  const Vec2 p0 = net.node(up).position;
  // At a confluence the main stem keeps its arriving chord, so the tributary's bend to meet it
  // (arrivalTangent) is measured from where the main stem really comes from.
  if (node.children.size() > 1)
    return normalize(p1 - p0);
  const double d01 = std::sqrt(distance(p0, p1)), d12 = std::sqrt(distance(p1, p2));
  const Vec2 m = (p1 - p0) / d01 - (p2 - p0) / (d01 + d12) + (p2 - p1) / d12;
  return lengthSquared(m) > 1e-18 ? normalize(m) : normalize(p2 - p1);
}

/// The direction the section from `id` arrives at its parent with (Section 7.1 junctions): the
/// parent's through tangent when it is the main inflow; otherwise the tributary bends to meet
/// the main stem there at 90° across Strahler orders and at 45° within one.
Vec2 arrivalTangent(const network::RiverNetwork& net, const analysis::NetworkAnalysis& a,
                    network::NodeId id) {
  const network::RiverNode& node = net.node(id);
  const Vec2 stem = throughTangent(net, a, node.parent);
  const network::NodeId main = mainInflow(net, a, node.parent);
  if (!main.valid() || main == id)
    return stem;
  const double side =
      cross(stem, node.position - net.node(node.parent).position) >= 0.0 ? 1.0 : -1.0;
  const bool sameOrder = net.node(main).strahler == node.strahler;
  return rotate(stem, -side * (sameOrder ? kPi / 4.0 : kPi / 2.0));
}

/// The side a section's meander belt keeps to near a confluence, +1 left, −1 right, 0 either:
/// a tributary's away from the main stem above the junction, the main stem's away from the
/// tributary, above the junction and below it, so that channels of different water levels do
/// not touch (two sibling channels 3 m apart read as a 2.7 m rise downstream).
double beltSide(const network::RiverNetwork& net, const analysis::NetworkAnalysis& a,
                network::NodeId id) {
  const network::RiverNode& node = net.node(id);
  const auto sideOf = [&](network::NodeId confluence, network::NodeId except) {
    const Vec2 stem = throughTangent(net, a, confluence);
    const Vec2 at = net.node(confluence).position;
    for (network::NodeId c : net.node(confluence).children)
      if (c != except)
        return cross(stem, net.node(c).position - at) >= 0.0 ? 1.0 : -1.0;
    return 0.0;
  };
  if (net.node(node.parent).children.size() > 1) {
    const network::NodeId main = mainInflow(net, a, node.parent);
    if (main != id)
      return sideOf(node.parent, main);
    return -sideOf(node.parent, id);
  }
  if (node.children.size() > 1)
    return -sideOf(id, mainInflow(net, a, id));
  return 0.0;
}

/// The whole sine-generated waves (MeanderWave) of a section of this type and mean channel
/// width along a valley `valleyLength` long, their belt on `side` (beltSide; 0: at random):
/// wavelengths of 10–14 channel widths down the valley (Langbein & Leopold 1966), at least
/// kMinMeanderWavelength; largest deflections ω of 1.3–1.6 rad for E (sinuosity 1.6–2.2) and
/// 0.1–0.25 rad for B (nearly straight), each wave's varied a little; the two waves nearest an
/// end at a confluence calmed (×0.5, ×0.85), so that the bends there keep clear of the other
/// river. None for deltas, or where no whole wave fits.
std::vector<MeanderWave> meanderWaves(RiverType type, double width, double valleyLength,
                                      double side, bool calmStart, bool calmEnd, base::Rng& rng) {
  const double wavelength = std::max(rng.uniform(10.0, 14.0) * width, kMinMeanderWavelength);
  const double drawnSide = rng.chance(0.5) ? 1.0 : -1.0;
  const double sign = side != 0.0 ? side : drawnSide;
  double omega = 0.0;
  if (type == RiverType::kSinuous)
    omega = rng.uniform(1.3, 1.6);
  else if (type == RiverType::kStraight)
    omega = rng.uniform(0.1, 0.25);
  const auto count = static_cast<std::size_t>(std::floor(valleyLength / wavelength + 0.5));
  std::vector<MeanderWave> waves;
  if (omega == 0.0 || count == 0)
    return waves;
  constexpr double kCalm[] = {0.5, 0.85};
  for (std::size_t i = 0; i < count; ++i) {
    MeanderWave w;
    w.omega = sign * omega * rng.uniform(0.92, 1.06);
    if (calmStart && i < 2)
      w.omega *= kCalm[i];
    if (calmEnd && count - 1 - i < 2)
      w.omega *= kCalm[count - 1 - i];
    w.flattening = rng.uniform(0.0, 0.03);
    w.length = rng.uniform(0.8, 1.2) * meanderSinuosity(w);
    waves.push_back(w);
  }
  return waves;
}

/// A sideways sine offset (perturb): the braided channels' jitter and the wandering under the
/// tributaries.
struct Meander {
  double amplitude = 0.0;
  double wavelength = 1.0;
  double phase = 0.0;
  double secondAmplitude = 0.0; // braided channels wander at two scales
};

/// The jitter of a braided (D) channel of this width.
Meander braidedJitter(double width, base::Rng& rng) {
  Meander m;
  m.wavelength = std::max(11.0 * width, kMinMeanderWavelength) * rng.uniform(0.85, 1.15);
  m.phase = rng.uniform(0.0, 2.0 * kPi);
  m.amplitude = 0.06 * m.wavelength;
  m.secondAmplitude = 0.03 * m.wavelength;
  return m;
}

/// The sideways offset of `m` at arc length s of a curve `total` long, fading to zero at both
/// ends (over `ramp` wavelengths, at most half the curve; smoothstep, so flat there too).
double offsetAt(const Meander& m, double s, double total, double ramp) {
  const double fadeLength = std::min(ramp * m.wavelength, 0.5 * total);
  const double fade = std::clamp(std::min(s, total - s) / fadeLength, 0.0, 1.0);
  const double t = 2.0 * kPi * s / m.wavelength + m.phase;
  const double offset = m.amplitude * std::sin(t) + m.secondAmplitude * std::sin(2.7 * t + 1.3);
  return offset * fade * fade * (3.0 - 2.0 * fade);
}

/// Offsets the points sideways by the meander (offsetAt), so that sections still meet exactly
/// at the nodes.
void perturb(std::vector<Vec2>& points, const Meander& m, double ramp = 0.5) {
  if (m.amplitude == 0.0 || points.size() < 3)
    return;
  std::vector<double> s{0.0};
  for (std::size_t i = 1; i < points.size(); ++i)
    s.push_back(s.back() + distance(points[i - 1], points[i]));
  std::vector<Vec2> out = points;
  for (std::size_t i = 1; i + 1 < points.size(); ++i) {
    const Vec2 tangent = points[i + 1] - points[i - 1];
    if (lengthSquared(tangent) == 0.0)
      continue;
    out[i] = points[i] + perpendicular(normalize(tangent)) * offsetAt(m, s[i], s.back(), ramp);
  }
  points = std::move(out);
}

/// Pulls the points back toward the straight edge [a, b] where the smoothing or the meander
/// took them nearer to Γ than `clearance` (or than the edge itself lies there): near the shore
/// the coast's cap holds every height below the shore distance, so a bed 55 m up passing 18 m
/// from a fjord's shore dipped to 18 m and rose again (Iceland, 248 profile violations).
void keepClearOfShore(std::vector<Vec2>& points, Vec2 a, Vec2 b, const geometry::PolygonIndex& land,
                      double clearance) {
  for (std::size_t i = 1; i + 1 < points.size(); ++i) {
    const Vec2 q = geometry::closestPointOnSegment(points[i], a, b);
    const double needed = std::min(clearance, land.distanceToBoundary(q, clearance));
    for (int halving = 0; halving < 6 && land.distanceToBoundary(points[i], needed) < needed;
         ++halving)
      points[i] = geometry::lerp(q, points[i], 0.5);
    if (land.distanceToBoundary(points[i], needed) < needed)
      points[i] = q;
  }
}

/// Whether every inner point of `points` keeps the clearance keepClearOfShore asks for.
bool clearOfShore(const std::vector<Vec2>& points, Vec2 a, Vec2 b,
                  const geometry::PolygonIndex& land, double clearance) {
  for (std::size_t i = 1; i + 1 < points.size(); ++i) {
    const Vec2 q = geometry::closestPointOnSegment(points[i], a, b);
    const double needed = std::min(clearance, land.distanceToBoundary(q, clearance));
    if (land.distanceToBoundary(points[i], needed) < needed)
      return false;
  }
  return true;
}

/// How a section's meander belt was sided (beltSide) and calmed (meanderWaves), for fitCurve.
struct SideRule {
  bool kept = false;      ///< The belt was put on the side away from another river.
  bool calmStart = false; ///< The section starts at a confluence.
  bool calmEnd = false;   ///< The section ends at a confluence or a mouth.
};

/// Extra calming of the wave next to a confluence when fitCurve mirrors a kept belt: mirrored
/// toward a sibling channel at a mouth, a bend ran 2 m from it and read as a 0.5 m rise.
constexpr double kMirroredCalm = 0.3;

/// Most turn between consecutive points of a fitted curve (fitCurve), radians: the curves are
/// cut at 20° (CurveSampling), so more means the valley's bend folded the meander over itself.
constexpr double kMostTurn = 28.0 * kPi / 180.0;

/// Room kept between a section's channel and a neighbouring channel beyond their half-widths,
/// m: a channel inside another's floor takes the lower of the two beds there, and the other bed
/// is another water level (Mallorca's two sources 80 m apart, one meandering across the other's
/// straight course to their mouth: 136 samples rising up to 1.9 m). 10 m also holds at zoom 14,
/// whose floors are 7 m wide (riverFloor).
constexpr double kChannelGap = 10.0;
/// Near the node two channels share they meet: within this many gaps of it, no check.
constexpr double kChannelMeeting = 3.0;

/// The channels a section's curve keeps clear of: its siblings (the other sections ending at
/// its downstream node), its upstream node's inflows and the section leaving its downstream
/// node, each with the node where they meet.
struct Neighbours {
  struct Channel {
    const RiverPrimitive* section; ///< Its curve is set.
    Vec2 meeting;                  ///< The node both channels touch.
  };
  std::vector<Channel> channels;
  double halfWidth = 0.0; ///< The section's own widest half-width, m.
};

/// Whether the channel `points` keeps kChannelGap beyond both half-widths from every
/// neighbouring channel, except within kChannelMeeting gaps of the node where they meet.
bool clearOfNeighbours(const std::vector<Vec2>& points, const Neighbours& neighbours) {
  for (const Neighbours::Channel& other : neighbours.channels) {
    const double gap = neighbours.halfWidth +
                       0.5 * std::max(other.section->widthUp, other.section->widthDown) +
                       kChannelGap;
    const double meeting = kChannelMeeting * gap;
    const std::vector<CurvePoint>& curve = other.section->curve;
    // The other curve in runs of kRun segments, each run's box grown by the gap: a segment
    // of ours outside a run's box is farther than the gap from all of its segments.
    constexpr std::size_t kRun = 8;
    std::vector<geometry::Aabb> runs;
    for (std::size_t k = 0; k + 1 < curve.size(); k += kRun) {
      geometry::Aabb box;
      for (std::size_t j = k; j < std::min(k + kRun + 1, curve.size()); ++j)
        box.add(curve[j].position);
      runs.push_back(box.expanded(gap));
    }
    for (std::size_t i = 0; i + 1 < points.size(); ++i) {
      if (distance(points[i], other.meeting) < meeting ||
          distance(points[i + 1], other.meeting) < meeting)
        continue;
      geometry::Aabb segment;
      segment.add(points[i]);
      segment.add(points[i + 1]);
      for (std::size_t run = 0; run < runs.size(); ++run) {
        if (!runs[run].intersects(segment))
          continue;
        for (std::size_t k = run * kRun; k < std::min((run + 1) * kRun, curve.size() - 1); ++k)
          if (geometry::segmentSegmentDistance(points[i], points[i + 1], curve[k].position,
                                               curve[k + 1].position) < gap)
            return false;
      }
    }
  }
  return true;
}

/// Whether `points` turn by at most kMostTurn from one segment to the next, keep clear of the
/// shore as keepClearOfShore asks, and keep clear of the neighbouring channels.
bool fits(const std::vector<Vec2>& points, Vec2 a, Vec2 b, const geometry::PolygonIndex& land,
          double clearance, const Neighbours& neighbours) {
  for (std::size_t i = 1; i + 1 < points.size(); ++i) {
    const Vec2 in = points[i] - points[i - 1], out = points[i + 1] - points[i];
    if (std::abs(std::atan2(cross(in, out), dot(in, out))) > kMostTurn)
      return false;
  }
  return clearOfShore(points, a, b, land, clearance) && clearOfNeighbours(points, neighbours);
}

/// The curve of `waves` along `valley` (from a to b) where it fits (bends smoothly, keeps clear
/// of the shore and of the neighbouring channels), or else the first that fits of: the waves
/// mirrored to the valley's other side (a belt on the inside of a tight valley bend folds), then
/// both sides with half and a quarter of the deflection (where `side` kept the belt away from the
/// other river at a confluence, the mirrored wave next to that confluence calmed to kMirroredCalm
/// more), the valley path alone, with arms of half and a quarter of their length (nearer the chord,
/// still leaving and arriving along the nodes' tangents), and last the straight chord (without
/// `shift`, the wandering). Pulling single points back toward the chord instead made corners of up
/// to 54°.
std::vector<Vec2> fitCurve(const ValleyPath& valley, std::vector<MeanderWave> waves, Vec2 a, Vec2 b,
                           const geometry::PolygonIndex& land, double clearance,
                           const std::function<double(double)>& shift, SideRule side,
                           const Neighbours& neighbours) {
  std::vector<Vec2> points = meanderCurve(valley, waves, {}, shift);
  if (fits(points, a, b, land, clearance, neighbours))
    return points;
  bool mirrored = false;
  for (const double scale : {-1.0, -0.5, -1.0, -0.5, -1.0}) {
    if (waves.empty())
      break;
    for (MeanderWave& w : waves)
      w.omega *= scale;
    if (!mirrored && side.kept) {
      // Mirrored toward the other river: the wave at the confluence nearly straight.
      if (side.calmStart)
        waves.front().omega *= kMirroredCalm;
      if (side.calmEnd)
        waves.back().omega *= kMirroredCalm;
    }
    mirrored = true;
    points = meanderCurve(valley, waves, {}, shift);
    if (fits(points, a, b, land, clearance, neighbours))
      return points;
  }
  for (const double arm : {1.0, 0.5, 0.25}) {
    points = meanderCurve(valley.withArms(arm), {}, {}, shift);
    if (fits(points, a, b, land, clearance, neighbours))
      return points;
  }
  const Vec2 chord = normalize(b - a);
  return meanderCurve(ValleyPath(a, chord, b, chord), {}, {});
}

/// A section's type, widths, depths and radius from the flows at its two ends.
RiverPrimitive sectionHead(const network::RiverNetwork& net, const analysis::NetworkAnalysis& a,
                           network::NodeId id) {
  const network::RiverNode& node = net.node(id);
  RiverPrimitive r;
  r.node = id;
  r.type = toRiverType(a.rosgen[id.index()]);
  r.widthUp = quantize(channelWidth(a.flow[id.index()]), Quantum::kRadius);
  r.widthDown = quantize(channelWidth(a.flow[node.parent.index()]), Quantum::kRadius);
  r.depthUp = quantize(channelDepth(a.flow[id.index()]), Quantum::kElevation);
  r.depthDown = quantize(channelDepth(a.flow[node.parent.index()]), Quantum::kElevation);
  r.radius = quantize(valleyRadius(r.type, std::max(r.widthUp, r.widthDown)), Quantum::kRadius);
  return r;
}

/// Sets r's curve to `points` (upstream node first), u_z falling linearly with arc length from
/// the upstream node to the downstream one, the ends exactly the two nodes.
void setCurve(RiverPrimitive& r, const network::RiverNetwork& net, network::NodeId id,
              const std::vector<Vec2>& points) {
  const network::RiverNode& node = net.node(id);
  const double zUp = node.elevation, zDown = net.node(node.parent).elevation;
  std::vector<double> s{0.0};
  for (std::size_t i = 1; i < points.size(); ++i)
    s.push_back(s.back() + distance(points[i - 1], points[i]));
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double z = zUp + (zDown - zUp) * (s.back() > 0 ? s[i] / s.back() : 1.0);
    r.curve.push_back({quantize(points[i]), quantize(z, Quantum::kElevation)});
  }
  r.curve.front() = {node.position, node.elevation};
  r.curve.back() = {net.node(node.parent).position, net.node(node.parent).elevation};
}

RiverPrimitive buildSection(const input::Params& params, const network::RiverNetwork& net,
                            const analysis::NetworkAnalysis& a, const geometry::PolygonIndex& land,
                            network::NodeId id, std::vector<Neighbours::Channel> neighbours) {
  const network::RiverNode& node = net.node(id);
  RiverPrimitive r = sectionHead(net, a, id);

  base::Rng rng(params.seed, base::mixHash(kRiverStream, id.value));
  const network::RiverNode& parent = net.node(node.parent);
  const ValleyPath valley(node.position, throughTangent(net, a, id), parent.position,
                          arrivalTangent(net, a, id));
  const double clearance = kShoreClearance * params.delta;
  std::function<double(double)> shift;
  Meander wander;
  if (params.tributaryLevels > 0) {
    // Under the tributaries, every river wanders at two scales, irregularly: a straight
    // channel of constant width over a kilometre was the first thing reviewers saw. The
    // valley wanders, and the meanders follow it.
    base::Rng wanderRng(params.seed, base::mixHash(kWanderStream, id.value));
    wander.wavelength = wanderRng.uniform(450.0, 900.0);
    wander.amplitude = wander.wavelength * wanderRng.uniform(0.05, 0.11);
    wander.phase = wanderRng.uniform(0.0, 2.0 * kPi);
    wander.secondAmplitude = wander.wavelength * wanderRng.uniform(0.02, 0.05);
    // Faded over a whole wavelength: near a confluence a section runs inside its parent's
    // valley, and pushed across the parent's floor its bed would dip and rise again.
    shift = [&wander, total = valley.length()](double x) {
      return offsetAt(wander, x, total, 1.0);
    };
  }
  std::vector<Vec2> points;
  if (r.type == RiverType::kBraided) {
    const Meander jitter = braidedJitter(r.widthUp, rng);
    const double step = std::min(50.0, jitter.wavelength / 6.0);
    const auto count =
        std::max<std::size_t>(2, static_cast<std::size_t>(std::ceil(valley.length() / step)));
    for (std::size_t k = 0; k <= count; ++k)
      points.push_back(
          valley.at(valley.length() * static_cast<double>(k) / static_cast<double>(count)));
    perturb(points, jitter);
    if (shift)
      perturb(points, wander, 1.0);
  } else {
    const double side = beltSide(net, a, id);
    const SideRule rule{side != 0.0, node.children.size() > 1,
                        parent.children.size() > 1 || !parent.parent.valid()};
    std::vector<MeanderWave> waves =
        meanderWaves(r.type, 0.5 * (r.widthUp + r.widthDown), valley.length(), side, rule.calmStart,
                     rule.calmEnd, rng);
    points = fitCurve(valley, std::move(waves), node.position, parent.position, land, clearance,
                      shift, rule, {std::move(neighbours), 0.5 * std::max(r.widthUp, r.widthDown)});
  }
  keepClearOfShore(points, node.position, parent.position, land, clearance);
  setCurve(r, net, id, points);
  return r;
}

/// Most spacing of the points of a drawn river's curve, m (as grown curves' below 50 m).
constexpr double kDrawnCurveStep = 50.0;

/// Key of a stored node position: its multiples of the position quantum.
using PositionKey = std::pair<long long, long long>;
PositionKey keyOf(Vec2 p) {
  return {std::llround(p.x / Quantum::kPosition), std::llround(p.y / Quantum::kPosition)};
}

/// The chains of the drawn rivers as the quantized network holds them: per stored node
/// position, the (river, chain index) of the chain nodes there.
struct DrawnChains {
  std::vector<std::optional<network::DrawnCourse>> courses;
  std::multimap<PositionKey, std::pair<std::size_t, std::size_t>> at;

  /// The course and chain index k of the edge from `id` to its parent when it joins chain
  /// nodes k and k − 1 of one drawn river; none otherwise.
  std::optional<std::pair<const network::DrawnCourse*, std::size_t>>
  edge(const network::RiverNetwork& net, network::NodeId id) const {
    const network::RiverNode& node = net.node(id);
    const auto [begin, end] = at.equal_range(keyOf(node.position));
    for (auto it = begin; it != end; ++it) {
      const auto [river, k] = it->second;
      const network::DrawnCourse& c = *courses[river];
      if (k > 0 && keyOf(net.node(node.parent).position) == keyOf(quantize(c.node(k - 1))))
        return std::make_pair(&c, k);
    }
    return std::nullopt;
  }
};

DrawnChains drawnChains(const input::Params& params, const geometry::PolygonIndex& land,
                        const input::Features& features) {
  DrawnChains chains;
  for (std::size_t r = 0; r < features.rivers.size(); ++r) {
    chains.courses.push_back(network::drawnCourse(features.rivers[r], land, params));
    if (const auto& c = chains.courses.back())
      for (std::size_t k = 0; k < c->chain.size(); ++k)
        chains.at.emplace(keyOf(quantize(c->node(k))), std::make_pair(r, k));
  }
  return chains;
}

/// The section of a drawn river between chain nodes k (id) and k − 1 (its parent): the drawn
/// line between them, every vertex kept, with no meander: the channel is carved where it was
/// drawn.
RiverPrimitive buildDrawnSection(const network::RiverNetwork& net,
                                 const analysis::NetworkAnalysis& a, network::NodeId id,
                                 const network::DrawnCourse& course, std::size_t k) {
  RiverPrimitive r = sectionHead(net, a, id);
  setCurve(r, net, id, course.subPath(course.chain[k], course.chain[k - 1], kDrawnCurveStep));
  return r;
}

} // namespace

RiverType toRiverType(analysis::RosgenType type) noexcept {
  switch (type) {
  case analysis::RosgenType::kStraight:
    return RiverType::kStraight;
  case analysis::RosgenType::kSinuous:
    return RiverType::kSinuous;
  case analysis::RosgenType::kBraided:
    return RiverType::kBraided;
  case analysis::RosgenType::kDelta:
    return RiverType::kDelta;
  }
  return RiverType::kSinuous;
}

double channelWidth(double flow) noexcept {
  return 4.0 * std::sqrt(std::max(flow, 0.0));
}

double channelDepth(double flow) noexcept {
  return 0.4 * std::pow(std::max(flow, 0.0), 0.4);
}

double valleyRadius(RiverType type, double width) noexcept {
  switch (type) {
  case RiverType::kStraight:
    return 240.0 + 40.0 * width;
  case RiverType::kSinuous:
    return 360.0 + 60.0 * width;
  case RiverType::kBraided:
    return 500.0 + 60.0 * width;
  case RiverType::kDelta:
    return 600.0 + 60.0 * width;
  }
  return 180.0;
}

std::vector<RiverPrimitive> generateRiverPrimitives(const input::Params& params,
                                                    const network::RiverNetwork& network,
                                                    const analysis::NetworkAnalysis& analysis,
                                                    const geometry::PolygonIndex& land,
                                                    const input::Features& features) {
  const DrawnChains chains = drawnChains(params, land, features);
  std::vector<RiverPrimitive> rivers;
  rivers.reserve(network.edgeCount());
  // Where each node's section is in `rivers`, once built: a section keeps clear of the
  // neighbouring sections built before it, then, where one built after it could not keep
  // clear of it, is built again clear of all of them.
  constexpr std::size_t kNotBuilt = ~std::size_t{0};
  std::vector<std::size_t> sectionOf(network.nodes.size(), kNotBuilt);
  const auto neighboursOf = [&](network::NodeId id) {
    std::vector<Neighbours::Channel> channels;
    const network::RiverNode& node = network.node(id);
    const auto add = [&](network::NodeId other, Vec2 meeting) {
      if (other != id && sectionOf[other.index()] != kNotBuilt)
        channels.push_back({&rivers[sectionOf[other.index()]], meeting});
    };
    for (network::NodeId c : network.node(node.parent).children)
      add(c, network.node(node.parent).position);
    for (network::NodeId c : node.children)
      add(c, node.position);
    add(node.parent, network.node(node.parent).position);
    return channels;
  };
  const auto drawnEdge = [&](network::NodeId id) {
    return chains.at.empty() ? std::nullopt : chains.edge(network, id);
  };
  for (std::uint32_t i = 0; i < network.nodes.size(); ++i) {
    if (!network.nodes[i].parent.valid())
      continue;
    const network::NodeId id(i);
    RiverPrimitive section;
    if (const auto drawn = drawnEdge(id)) {
      section = buildDrawnSection(network, analysis, id, *drawn->first, drawn->second);
    } else {
      section = buildSection(params, network, analysis, land, id, neighboursOf(id));
    }
    sectionOf[i] = rivers.size();
    rivers.push_back(std::move(section));
  }
  for (std::uint32_t i = 0; i < network.nodes.size(); ++i) {
    const network::NodeId id(i);
    if (sectionOf[i] == kNotBuilt || drawnEdge(id))
      continue;
    RiverPrimitive& section = rivers[sectionOf[i]];
    std::vector<Neighbours::Channel> neighbours = neighboursOf(id);
    std::vector<Vec2> points;
    for (const CurvePoint& q : section.curve)
      points.push_back(q.position);
    if (!clearOfNeighbours(points,
                           {neighbours, 0.5 * std::max(section.widthUp, section.widthDown)}))
      section = buildSection(params, network, analysis, land, id, std::move(neighbours));
  }
  return rivers;
}

} // namespace strahler::primitives
