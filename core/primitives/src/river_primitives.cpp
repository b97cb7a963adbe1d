#include "strahler/primitives/river_primitives.h"

#include "strahler/base/random.h"
#include "strahler/geometry/distance.h"
#include "strahler/network/drawn_rivers.h"
#include "strahler/primitives/quantization.h"

#include <algorithm>
#include <cmath>
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

/// Control polygon of the section from `node` down to its parent (Section 7.1 junctions).
std::vector<Vec2> controlPolygon(const input::Params& params, const network::RiverNetwork& net,
                                 const analysis::NetworkAnalysis& a, network::NodeId id) {
  const network::RiverNode& node = net.node(id);
  const Vec2 c = node.position;
  const Vec2 n = net.node(node.parent).position;
  const double length = distance(c, n);
  std::vector<Vec2> points{c};
  // Leave the upstream node in the direction the main inflow arrives with.
  if (const network::NodeId up = mainInflow(net, a, id); up.valid()) {
    const Vec2 arriving = normalize(c - net.node(up).position);
    points.push_back(c + arriving * (0.25 * std::min(params.edgeLength, length)));
  }
  // Tributaries bend to meet the main stem: 90° across Strahler orders, 45° within one.
  const network::NodeId main = mainInflow(net, a, node.parent);
  if (main.valid() && main != id) {
    const Vec2 stem = normalize(n - net.node(main).position);
    const double side = cross(stem, c - n) >= 0.0 ? 1.0 : -1.0;
    const bool sameOrder = net.node(main).strahler == node.strahler;
    const Vec2 arrival = rotate(stem, -side * (sameOrder ? kPi / 4.0 : kPi / 2.0));
    points.push_back(n - arrival * (0.35 * std::min(params.edgeLength, length)));
  }
  points.push_back(n);
  return points;
}

/// Chaikin corner cutting with fixed end points.
std::vector<Vec2> smooth(std::vector<Vec2> points, int iterations) {
  for (int it = 0; it < iterations && points.size() > 2; ++it) {
    std::vector<Vec2> out{points.front()};
    for (std::size_t i = 0; i + 1 < points.size(); ++i) {
      const Vec2 a = points[i], b = points[i + 1];
      if (i > 0)
        out.push_back(lerp(a, b, 0.25));
      if (i + 2 < points.size())
        out.push_back(lerp(a, b, 0.75));
    }
    out.push_back(points.back());
    points = std::move(out);
  }
  return points;
}

/// Arc-length resampling at `count` + 1 uniformly spaced points.
std::vector<Vec2> resample(const std::vector<Vec2>& points, std::size_t count) {
  std::vector<double> cumulative{0.0};
  for (std::size_t i = 1; i < points.size(); ++i)
    cumulative.push_back(cumulative.back() + distance(points[i - 1], points[i]));
  const double total = cumulative.back();
  std::vector<Vec2> out;
  std::size_t seg = 0;
  for (std::size_t k = 0; k <= count; ++k) {
    const double s = total * static_cast<double>(k) / static_cast<double>(count);
    while (seg + 2 < cumulative.size() && cumulative[seg + 1] < s)
      ++seg;
    const double span = cumulative[seg + 1] - cumulative[seg];
    out.push_back(lerp(points[seg], points[seg + 1], span > 0 ? (s - cumulative[seg]) / span : 0));
  }
  out.back() = points.back();
  return out;
}

struct Meander {
  double amplitude = 0.0;
  double wavelength = 1.0;
  double phase = 0.0;
  double secondAmplitude = 0.0; // braided channels wander at two scales
};

Meander meanderFor(RiverType type, double width, base::Rng& rng) {
  Meander m;
  m.wavelength = std::max(11.0 * width, kMinMeanderWavelength) * rng.uniform(0.85, 1.15);
  m.phase = rng.uniform(0.0, 2.0 * kPi);
  switch (type) {
  case RiverType::kSinuous:
    m.amplitude = 0.22 * m.wavelength * rng.uniform(0.7, 1.0);
    break;
  case RiverType::kStraight:
    m.amplitude = 0.03 * m.wavelength;
    break;
  case RiverType::kBraided:
    m.amplitude = 0.06 * m.wavelength;
    m.secondAmplitude = 0.03 * m.wavelength;
    break;
  case RiverType::kDelta:
    break;
  }
  return m;
}

/// Offsets the points sideways by the meander, fading to zero at both ends (over `ramp`
/// wavelengths, at most half the section) so that sections still meet exactly at the nodes.
void perturb(std::vector<Vec2>& points, const Meander& m, double ramp = 0.5) {
  if (m.amplitude == 0.0 || points.size() < 3)
    return;
  std::vector<double> s{0.0};
  for (std::size_t i = 1; i < points.size(); ++i)
    s.push_back(s.back() + distance(points[i - 1], points[i]));
  const double total = s.back();
  const double fadeLength = std::min(ramp * m.wavelength, 0.5 * total);
  std::vector<Vec2> out = points;
  for (std::size_t i = 1; i + 1 < points.size(); ++i) {
    const Vec2 tangent = points[i + 1] - points[i - 1];
    if (lengthSquared(tangent) == 0.0)
      continue;
    const Vec2 normal = perpendicular(normalize(tangent));
    const double fade = std::min({1.0, s[i] / fadeLength, (total - s[i]) / fadeLength});
    const double t = 2.0 * kPi * s[i] / m.wavelength + m.phase;
    const double offset = m.amplitude * std::sin(t) + m.secondAmplitude * std::sin(2.7 * t + 1.3);
    out[i] = points[i] + normal * (offset * fade * fade * (3.0 - 2.0 * fade));
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
                            network::NodeId id) {
  const network::RiverNode& node = net.node(id);
  RiverPrimitive r = sectionHead(net, a, id);

  base::Rng rng(params.seed, base::mixHash(kRiverStream, id.value));
  const Meander meander = meanderFor(r.type, r.widthUp, rng);
  std::vector<Vec2> points = smooth(controlPolygon(params, net, a, id), 2);
  const double step = std::min(50.0, meander.wavelength / 6.0);
  double length = 0.0;
  for (std::size_t i = 1; i < points.size(); ++i)
    length += distance(points[i - 1], points[i]);
  points = resample(points,
                    std::max<std::size_t>(2, static_cast<std::size_t>(std::ceil(length / step))));
  perturb(points, meander);
  if (params.tributaryLevels > 0) {
    // Under the tributaries, every river wanders at two scales, irregularly: a straight
    // channel of constant width over a kilometre was the first thing reviewers saw.
    base::Rng wanderRng(params.seed, base::mixHash(kWanderStream, id.value));
    Meander wander;
    wander.wavelength = wanderRng.uniform(450.0, 900.0);
    wander.amplitude = wander.wavelength * wanderRng.uniform(0.05, 0.11);
    wander.phase = wanderRng.uniform(0.0, 2.0 * kPi);
    wander.secondAmplitude = wander.wavelength * wanderRng.uniform(0.02, 0.05);
    // Faded over a whole wavelength: near a confluence a section runs inside its parent's
    // valley, and pushed across the parent's floor its bed would dip and rise again.
    perturb(points, wander, 1.0);
  }
  keepClearOfShore(points, node.position, net.node(node.parent).position, land,
                   kShoreClearance * params.delta);
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
  for (std::uint32_t i = 0; i < network.nodes.size(); ++i) {
    if (!network.nodes[i].parent.valid())
      continue;
    const network::NodeId id(i);
    if (const auto drawn = chains.at.empty() ? std::nullopt : chains.edge(network, id))
      rivers.push_back(buildDrawnSection(network, analysis, id, *drawn->first, drawn->second));
    else
      rivers.push_back(buildSection(params, network, analysis, land, id));
  }
  return rivers;
}

} // namespace strahler::primitives
