#include "relief_field.h"

#include <algorithm>
#include <cmath>

namespace strahler::construction::detail {
namespace {

/// Levels above the stored lattice (64 × its spacing at the top: 3.8 km at 60 m).
constexpr int kLevels = 7;

/// Catmull-Rom weights of the nodes at −1, 0, 1, 2 for a point t ∈ [0, 1) past node 0.
void catmullRom(double t, double w[4]) noexcept {
  const double t2 = t * t, t3 = t2 * t;
  w[0] = 0.5 * (-t3 + 2.0 * t2 - t);
  w[1] = 0.5 * (3.0 * t3 - 5.0 * t2 + 2.0);
  w[2] = 0.5 * (-3.0 * t3 + 4.0 * t2 + t);
  w[3] = 0.5 * (t3 - t2);
}

} // namespace

ReliefField::ReliefField(const ReliefResidual& residual) {
  Level base;
  base.spacing = residual.spacing;
  base.inverse = 1.0 / residual.spacing;
  base.column0 = residual.column0;
  base.row0 = residual.row0;
  base.columns = residual.columns;
  base.rows = residual.rows;
  base.values.resize(residual.quanta.size());
  for (std::size_t i = 0; i < base.values.size(); ++i)
    base.values[i] = static_cast<float>(residual.quanta[i] * ReliefResidual::kQuantum);
  levels_.push_back(std::move(base));
  while (static_cast<int>(levels_.size()) < kLevels) {
    const Level& below = levels_.back();
    if (below.columns < 8 || below.rows < 8 || below.column0 % 2 != 0 || below.row0 % 2 != 0)
      break;
    Level up;
    up.spacing = 2.0 * below.spacing;
    up.inverse = 1.0 / up.spacing;
    up.column0 = below.column0 / 2;
    up.row0 = below.row0 / 2;
    up.columns = below.columns / 2;
    up.rows = below.rows / 2;
    up.values.assign(static_cast<std::size_t>(up.columns) * static_cast<std::size_t>(up.rows),
                     0.0f);
    const auto value = [&](int c, int r) -> double {
      if (c < 0 || r < 0 || c >= below.columns || r >= below.rows)
        return 0.0;
      return below.values[static_cast<std::size_t>(r) * static_cast<std::size_t>(below.columns) +
                          static_cast<std::size_t>(c)];
    };
    constexpr double kTent[3] = {0.25, 0.5, 0.25};
    for (int r = 0; r < up.rows; ++r)
      for (int c = 0; c < up.columns; ++c) {
        double sum = 0.0;
        for (int dr = -1; dr <= 1; ++dr)
          for (int dc = -1; dc <= 1; ++dc)
            sum += kTent[dr + 1] * kTent[dc + 1] * value(2 * c + dc, 2 * r + dr);
        up.values[static_cast<std::size_t>(r) * static_cast<std::size_t>(up.columns) +
                  static_cast<std::size_t>(c)] = static_cast<float>(sum);
      }
    levels_.push_back(std::move(up));
  }
}

const ReliefField::Level& ReliefField::levelFor(double spacing) const noexcept {
  std::size_t k = 0;
  while (k + 1 < levels_.size() && levels_[k + 1].spacing <= spacing)
    ++k;
  return levels_[k];
}

double ReliefField::interpolate(const Level& level, geometry::Vec2 p) noexcept {
  const double u = p.x * level.inverse - static_cast<double>(level.column0);
  const double v = p.y * level.inverse - static_cast<double>(level.row0);
  if (!(u > 1.0 && v > 1.0 && u < level.columns - 3.0 && v < level.rows - 3.0))
    return 0.0; // the lattice's margin is sea, where the residual is 0
  const double fu = std::floor(u), fv = std::floor(v);
  double wu[4], wv[4];
  catmullRom(u - fu, wu);
  catmullRom(v - fv, wv);
  const auto c = static_cast<std::size_t>(fu) - 1, r = static_cast<std::size_t>(fv) - 1;
  const auto columns = static_cast<std::size_t>(level.columns);
  double sum = 0.0;
  for (std::size_t j = 0; j < 4; ++j) {
    const float* row = level.values.data() + (r + j) * columns + c;
    const double across = wu[0] * row[0] + wu[1] * row[1] + wu[2] * row[2] + wu[3] * row[3];
    sum += wv[j] * across;
  }
  return sum;
}

double ReliefField::at(geometry::Vec2 p, double spacing) const noexcept {
  return interpolate(levelFor(spacing), p);
}

} // namespace strahler::construction::detail
