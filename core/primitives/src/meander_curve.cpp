#include "strahler/primitives/meander_curve.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace strahler::primitives {
namespace {

using geometry::Vec2;

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kValleyStep = 5.0;   // m between the valley's arc-length table entries
constexpr int kStepsPerWave = 96;     // integration steps of one meander wave
constexpr double kStraightStep = 5.0; // m between the dense points of a valley without waves

double deflection(const MeanderWave& w, double phase) noexcept {
  return w.omega * std::sin(phase) -
         w.flattening * w.omega * w.omega * w.omega * std::sin(3.0 * phase);
}

/// Turning angle from direction a to direction b, radians in [0, π].
double turn(Vec2 a, Vec2 b) noexcept {
  return std::abs(std::atan2(cross(a, b), dot(a, b)));
}

/// The points of `dense` kept so that no span between kept points turns by more than
/// `sampling.maxTurn` or runs longer than `sampling.maxStep`; the ends always kept.
std::vector<Vec2> decimate(const std::vector<Vec2>& dense, const CurveSampling& sampling) {
  std::vector<Vec2> out{dense.front()};
  double turned = 0.0, run = 0.0;
  for (std::size_t i = 1; i < dense.size(); ++i) {
    const Vec2 d = dense[i] - dense[i - 1];
    const double joint = i >= 2 ? turn(dense[i - 1] - dense[i - 2], d) : 0.0;
    turned += joint;
    run += length(d);
    if ((turned > sampling.maxTurn || run > sampling.maxStep) && i >= 2 &&
        !(out.back() == dense[i - 1])) {
      out.push_back(dense[i - 1]);
      turned = joint;
      run = length(d);
    }
  }
  out.push_back(dense.back());
  return out;
}

} // namespace

ValleyPath::ValleyPath(Vec2 from, Vec2 leave, Vec2 to, Vec2 arrive, double arm)
    : leave_(leave), arrive_(arrive) {
  const double reach = arm * distance(from, to) / 3.0;
  control_[0] = from;
  control_[1] = from + leave * reach;
  control_[2] = to - arrive * reach;
  control_[3] = to;
  const int steps =
      std::clamp(static_cast<int>(std::ceil(distance(from, to) / kValleyStep)), 16, 4096);
  arc_.reserve(static_cast<std::size_t>(steps) + 1);
  arc_.push_back(0.0);
  Vec2 previous = from;
  for (int k = 1; k <= steps; ++k) {
    const double u = static_cast<double>(k) / steps, v = 1.0 - u;
    const Vec2 p = control_[0] * (v * v * v) + control_[1] * (3.0 * v * v * u) +
                   control_[2] * (3.0 * v * u * u) + control_[3] * (u * u * u);
    arc_.push_back(arc_.back() + distance(previous, p));
    previous = p;
  }
}

ValleyPath ValleyPath::withArms(double arm) const {
  return ValleyPath(control_[0], leave_, control_[3], arrive_, arm);
}

double ValleyPath::parameterAt(double x) const noexcept {
  if (x <= 0.0)
    return 0.0;
  if (x >= arc_.back())
    return 1.0;
  const auto k = static_cast<std::size_t>(std::upper_bound(arc_.begin(), arc_.end(), x) -
                                          arc_.begin()); // arc_[k − 1] ≤ x < arc_[k]
  const double span = arc_[k] - arc_[k - 1];
  const double t = span > 0.0 ? (x - arc_[k - 1]) / span : 0.0;
  return (static_cast<double>(k - 1) + t) / static_cast<double>(arc_.size() - 1);
}

Vec2 ValleyPath::at(double x) const noexcept {
  if (x < 0.0)
    return control_[0] + tangent(0.0) * x;
  if (x > length())
    return control_[3] + tangent(length()) * (x - length());
  const double u = parameterAt(x), v = 1.0 - u;
  return control_[0] * (v * v * v) + control_[1] * (3.0 * v * v * u) +
         control_[2] * (3.0 * v * u * u) + control_[3] * (u * u * u);
}

Vec2 ValleyPath::tangent(double x) const noexcept {
  const double u = parameterAt(x), v = 1.0 - u;
  const Vec2 d = (control_[1] - control_[0]) * (v * v) +
                 (control_[2] - control_[1]) * (2.0 * v * u) +
                 (control_[3] - control_[2]) * (u * u);
  if (lengthSquared(d) > 1e-12)
    return normalize(d);
  const Vec2 chord = control_[3] - control_[0];
  return lengthSquared(chord) > 0.0 ? normalize(chord) : Vec2{1.0, 0.0};
}

double meanderSinuosity(const MeanderWave& wave) noexcept {
  constexpr int kSteps = 512;
  double along = 0.0;
  for (int k = 0; k < kSteps; ++k)
    along += std::cos(deflection(wave, kTwoPi * (k + 0.5) / kSteps));
  return along > 0.0 ? kSteps / along : 1e9;
}

std::vector<Vec2> meanderCurve(const ValleyPath& valley, const std::vector<MeanderWave>& waves,
                               const CurveSampling& sampling,
                               const std::function<double(double)>& shift) {
  const double total = valley.length();
  // The channel in the valley's frame: x along the valley, y to its left.
  std::vector<Vec2> local{{0.0, 0.0}};
  for (const MeanderWave& w : waves) {
    const double ds = w.length / kStepsPerWave;
    for (int k = 0; k < kStepsPerWave; ++k) {
      const double theta = deflection(w, kTwoPi * (k + 0.5) / kStepsPerWave);
      local.push_back(local.back() + Vec2{std::cos(theta), std::sin(theta)} * ds);
    }
  }
  std::vector<Vec2> dense;
  if (local.size() < 2 || local.back().x <= 0.0) {
    const int steps = std::max(2, static_cast<int>(std::ceil(total / kStraightStep)));
    for (int k = 0; k <= steps; ++k) {
      const double x = total * k / steps;
      dense.push_back(shift ? valley.at(x) + perpendicular(valley.tangent(x)) * shift(x)
                            : valley.at(x));
    }
  } else {
    // Whole waves end on the axis; the shear removes the integration's rounding.
    const Vec2 end = local.back();
    const double scale = total / end.x;
    for (const Vec2& q : local) {
      const double x = q.x * scale;
      const double y = (q.y - end.y * q.x / end.x) * scale + (shift ? shift(x) : 0.0);
      dense.push_back(valley.at(x) + perpendicular(valley.tangent(x)) * y);
    }
  }
  dense.front() = valley.at(0.0);
  dense.back() = valley.at(total);
  return decimate(dense, sampling);
}

} // namespace strahler::primitives
