#include "rtin.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>

namespace strahler::encoding::rtin {
namespace {

/// A right isosceles triangle of the hierarchy: hypotenuse a–b, right angle at c (sample
/// coordinates). Its children split it along c–m, m the hypotenuse's midpoint.
struct Triangle {
  int ax, ay, bx, by, cx, cy;
};

Triangle firstChild(const Triangle& t) {
  const int mx = (t.ax + t.bx) / 2, my = (t.ay + t.by) / 2;
  return {t.ax, t.ay, t.cx, t.cy, mx, my};
}

Triangle secondChild(const Triangle& t) {
  const int mx = (t.ax + t.bx) / 2, my = (t.ay + t.by) / 2;
  return {t.cx, t.cy, t.bx, t.by, mx, my};
}

class Triangulator {
public:
  Triangulator(const Grid& grid, const Limits& limits)
      : grid_(grid), limits_(limits), n_(grid.samples), size_(grid.samples - 1),
        keep_(static_cast<std::size_t>(n_) * static_cast<std::size_t>(n_), 0) {
    while ((1 << levels_) < size_)
      ++levels_;
    // Two halvings per power of two; the last level's triangles span one cell.
    splittableDepths_ = 2 * levels_;
    buildCurvatureTables();
  }

  Mesh run() {
    for (int i = 0; i < n_; ++i) {
      keep(i, 0) = 1;
      keep(i, size_) = 1;
      keep(0, i) = 1;
      keep(size_, i) = 1;
    }
    const Triangle roots[2] = {{0, 0, size_, size_, size_, 0}, {size_, size_, 0, 0, 0, size_}};
    // Finest level first, so a triangle sees its children's (and their neighbours') decisions.
    for (int depth = splittableDepths_ - 1; depth >= 0; --depth)
      for (const Triangle& root : roots)
        forEachAtDepth(root, depth, depth);
    Mesh mesh;
    for (const Triangle& root : roots)
      emit(root, 0, mesh);
    return mesh;
  }

private:
  unsigned char& keep(int x, int y) {
    return keep_[static_cast<std::size_t>(y) * static_cast<std::size_t>(n_) +
                 static_cast<std::size_t>(x)];
  }

  double height(int x, int y) const {
    return grid_.heights[static_cast<std::size_t>(y) * static_cast<std::size_t>(n_) +
                         static_cast<std::size_t>(x)];
  }

  void buildCurvatureTables() {
    const double half = 0.5 * limits_.maxAngle;
    curvatureApplies_ = half < 0.5 * std::numbers::pi; // no side can span more than π
    const double s = std::sin(half);
    maxHaversine_ = s * s;
    cosLatitude_.resize(static_cast<std::size_t>(n_));
    halfLongitude_.resize(static_cast<std::size_t>(n_));
    halfLatitude_.resize(static_cast<std::size_t>(n_));
    for (int i = 0; i < n_; ++i) {
      const auto k = static_cast<std::size_t>(i);
      cosLatitude_[k] = std::cos(grid_.latitudes[k]);
      const double dLon = 0.5 * (grid_.longitudes[k] - grid_.longitudes[0]);
      const double dLat = 0.5 * (grid_.latitudes[k] - grid_.latitudes[0]);
      halfLongitude_[k] = std::sin(dLon) * std::sin(dLon);
      halfLatitude_[k] = std::sin(dLat) * std::sin(dLat);
    }
  }

  /// True when the side a–b spans more than maxAngle (haversine on the unit sphere).
  bool tooLong(const Triangle& t) const {
    if (!curvatureApplies_)
      return false;
    const auto dx = static_cast<std::size_t>(std::abs(t.bx - t.ax));
    const auto dy = static_cast<std::size_t>(std::abs(t.by - t.ay));
    const double h = halfLatitude_[dy] + cosLatitude_[static_cast<std::size_t>(t.ay)] *
                                             cosLatitude_[static_cast<std::size_t>(t.by)] *
                                             halfLongitude_[dx];
    return h > maxHaversine_;
  }

  template <class F> void visit(const Triangle& t, int depth, F&& f) {
    if (depth == 0) {
      f(t);
      return;
    }
    visit(firstChild(t), depth - 1, f);
    visit(secondChild(t), depth - 1, f);
  }

  void forEachAtDepth(const Triangle& root, int depth, int absoluteDepth) {
    visit(root, depth, [&](const Triangle& t) { decide(t, absoluteDepth); });
  }

  /// Marks t's hypotenuse midpoint as a vertex when t must be split.
  void decide(const Triangle& t, int depth) {
    unsigned char& mid = keep((t.ax + t.bx) / 2, (t.ay + t.by) / 2);
    if (mid)
      return;
    if (depth + 1 < splittableDepths_ &&
        (keep((t.ax + t.cx) / 2, (t.ay + t.cy) / 2) || keep((t.bx + t.cx) / 2, (t.by + t.cy) / 2)))
      mid = 1;
    else if (tooLong(t) || deviation(t, limits_.maxError) > limits_.maxError)
      mid = 1;
  }

  /// The largest vertical distance of a sample in t (edges included) from t's plane, or some
  /// value above `stopAbove` as soon as one is found.
  double deviation(const Triangle& t, double stopAbove) const {
    const double ha = height(t.ax, t.ay), hb = height(t.bx, t.by), hc = height(t.cx, t.cy);
    const double ux = t.bx - t.ax, uy = t.by - t.ay, uh = hb - ha;
    const double vx = t.cx - t.ax, vy = t.cy - t.ay, vh = hc - ha;
    const double nz = ux * vy - uy * vx;
    const double gx = -(uy * vh - uh * vy) / nz; // dh/dx
    const double gy = -(uh * vx - ux * vh) / nz; // dh/dy
    // Edge functions of the counter-clockwise order: a sample is inside when all are ≥ 0.
    const int sign = nz > 0 ? 1 : -1;
    const int px[3] = {t.ax, t.bx, t.cx}, py[3] = {t.ay, t.by, t.cy};
    const int x0 = std::min({t.ax, t.bx, t.cx}), x1 = std::max({t.ax, t.bx, t.cx});
    const int y0 = std::min({t.ay, t.by, t.cy}), y1 = std::max({t.ay, t.by, t.cy});
    double worst = 0.0;
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        bool inside = true;
        for (int e = 0; e < 3 && inside; ++e) {
          const int f = (e + 1) % 3;
          const int side = (px[f] - px[e]) * (y - py[e]) - (py[f] - py[e]) * (x - px[e]);
          inside = sign * side >= 0;
        }
        if (!inside)
          continue;
        const double plane = ha + gx * (x - t.ax) + gy * (y - t.ay);
        worst = std::max(worst, std::fabs(height(x, y) - plane));
      }
      if (worst > stopAbove)
        return worst;
    }
    return worst;
  }

  void emit(const Triangle& t, int depth, Mesh& mesh) {
    if (depth < splittableDepths_ && keep((t.ax + t.bx) / 2, (t.ay + t.by) / 2)) {
      emit(firstChild(t), depth + 1, mesh);
      emit(secondChild(t), depth + 1, mesh);
      return;
    }
    mesh.maxError =
        std::max(mesh.maxError, deviation(t, std::numeric_limits<double>::infinity()));
    const auto index = [this](int x, int y) { return static_cast<std::uint32_t>(y * n_ + x); };
    const long turn = static_cast<long>(t.bx - t.ax) * (t.cy - t.ay) -
                      static_cast<long>(t.by - t.ay) * (t.cx - t.ax);
    mesh.triangles.push_back(index(t.ax, t.ay));
    if (turn > 0) {
      mesh.triangles.push_back(index(t.bx, t.by));
      mesh.triangles.push_back(index(t.cx, t.cy));
    } else {
      mesh.triangles.push_back(index(t.cx, t.cy));
      mesh.triangles.push_back(index(t.bx, t.by));
    }
  }

  const Grid& grid_;
  const Limits& limits_;
  int n_;
  int size_;
  std::vector<unsigned char> keep_;
  int levels_ = 0;
  int splittableDepths_ = 0;
  bool curvatureApplies_ = true;
  double maxHaversine_ = 0.0;
  std::vector<double> cosLatitude_, halfLongitude_, halfLatitude_;
};

} // namespace

Mesh triangulate(const Grid& grid, const Limits& limits) {
  return Triangulator(grid, limits).run();
}

} // namespace strahler::encoding::rtin
