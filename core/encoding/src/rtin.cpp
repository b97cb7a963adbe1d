#include "rtin.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
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

/// Every splittable triangle of a grid's hierarchy, breadth first: the two roots (splitting
/// the square along its diagonal), then each level's children in order, so level d holds
/// indices [2^(d+1) − 2, 2^(d+2) − 2).
struct Hierarchy {
  /// A triangle in 12 bytes (grids have at most 1,025 samples a side).
  struct Packed {
    std::int16_t ax, ay, bx, by, cx, cy;
  };
  std::vector<Packed> triangles;

  static Packed pack(const Triangle& t) {
    const auto c = [](int v) { return static_cast<std::int16_t>(v); };
    return {c(t.ax), c(t.ay), c(t.bx), c(t.by), c(t.cx), c(t.cy)};
  }
  Triangle at(std::size_t k) const {
    const Packed& p = triangles[k];
    return {p.ax, p.ay, p.bx, p.by, p.cx, p.cy};
  }
};

std::size_t depthOf(std::size_t index) {
  return static_cast<std::size_t>(std::bit_width(index + 2)) - 2;
}

std::shared_ptr<const Hierarchy> buildHierarchy(int size, int splittableDepths) {
  auto hierarchy = std::make_shared<Hierarchy>();
  std::vector<Hierarchy::Packed>& all = hierarchy->triangles;
  const std::size_t count = (std::size_t{2} << splittableDepths) - 2;
  all.reserve(count);
  all.push_back(Hierarchy::pack({0, 0, size, size, size, 0}));
  all.push_back(Hierarchy::pack({size, size, 0, 0, 0, size}));
  for (std::size_t k = 0; all.size() < count; ++k) {
    const Triangle parent = hierarchy->at(k);
    all.push_back(Hierarchy::pack(firstChild(parent)));
    all.push_back(Hierarchy::pack(secondChild(parent)));
  }
  return hierarchy;
}

int levelsOf(int size) {
  return std::bit_width(static_cast<unsigned>(size)) - 1;
}

/// The hierarchy of a 2^k-cell grid: built once per size up to 256 cells and shared (1.5 MB at
/// 256), built per call above (25 MB at 1,024 cells: not worth keeping).
std::shared_ptr<const Hierarchy> hierarchyFor(int size) {
  constexpr int kLargestCached = 256;
  if (size > kLargestCached)
    return buildHierarchy(size, 2 * levelsOf(size));
  static std::mutex mutex;
  static std::map<int, std::shared_ptr<const Hierarchy>> cache;
  const std::lock_guard lock(mutex);
  std::shared_ptr<const Hierarchy>& entry = cache[size];
  if (!entry)
    entry = buildHierarchy(size, 2 * levelsOf(size));
  return entry;
}

class Triangulator {
public:
  Triangulator(const Grid& grid, const Limits& limits)
      : grid_(grid), limits_(limits), n_(grid.samples), size_(grid.samples - 1),
        keep_(static_cast<std::size_t>(n_) * static_cast<std::size_t>(n_), 0),
        bound_(keep_.size(), 0.0) {
    // Two halvings per power of two; the last level's triangles span one cell.
    splittableDepths_ = 2 * levelsOf(size_);
    buildCurvatureTables();
  }

  Mesh run() {
    for (int i = 0; i < n_; ++i) {
      keep(i, 0) = 1;
      keep(i, size_) = 1;
      keep(0, i) = 1;
      keep(size_, i) = 1;
    }
    // Finest level first, so a triangle sees its children's (and their neighbours') decisions.
    const std::shared_ptr<const Hierarchy> hierarchy = hierarchyFor(size_);
    for (std::size_t k = hierarchy->triangles.size(); k-- > 0;)
      decide(hierarchy->at(k), depthOf(k));
    Mesh mesh;
    for (std::size_t k = 0; k < 2; ++k)
      emit(hierarchy->at(k), 0, mesh);
    return mesh;
  }

private:
  /// An upper bound of the error of the unsplit triangles whose hypotenuse midpoint is (x, y).
  double& bound(int x, int y) {
    return bound_[static_cast<std::size_t>(y) * static_cast<std::size_t>(n_) +
                  static_cast<std::size_t>(x)];
  }

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

  /// Marks t's hypotenuse midpoint as a vertex when t must be split.
  void decide(const Triangle& t, std::size_t depth) {
    unsigned char& mid = keep((t.ax + t.bx) / 2, (t.ay + t.by) / 2);
    if (mid)
      return;
    if (depth + 1 < static_cast<std::size_t>(splittableDepths_) &&
        (keep((t.ax + t.cx) / 2, (t.ay + t.cy) / 2) || keep((t.bx + t.cx) / 2, (t.by + t.cy) / 2)))
      mid = 1;
    else if (tooLong(t) || !withinError(t, depth))
      mid = 1;
  }

  /// Whether every sample in t lies within maxError of t's plane. The children's errors bound
  /// t's: on each child t's plane differs from the child's by at most the hypotenuse midpoint's
  /// distance from t's plane, so the samples are scanned only when that bound is too loose.
  bool withinError(const Triangle& t, std::size_t depth) {
    const int mx = (t.ax + t.bx) / 2, my = (t.ay + t.by) / 2;
    const double local =
        std::fabs(height(mx, my) - 0.5 * (height(t.ax, t.ay) + height(t.bx, t.by)));
    double childError = 0.0; // the finest splittable triangles' children hold only vertices
    if (depth + 1 < static_cast<std::size_t>(splittableDepths_))
      childError = std::max(bound((t.ax + t.cx) / 2, (t.ay + t.cy) / 2),
                            bound((t.bx + t.cx) / 2, (t.by + t.cy) / 2));
    double error = childError + local;
    if (error > limits_.maxError) {
      error = deviation(t, limits_.maxError);
      if (error > limits_.maxError)
        return false;
    }
    double& known = bound(mx, my);
    known = std::max(known, error);
    return true;
  }

  /// Calls f(y, low, high) for each row of samples in t: columns low..high. The triangles are
  /// right isosceles on the grid, so every span is exact without division.
  template <class F> static void forEachRow(const Triangle& t, F&& f) {
    if (t.ay == t.by || t.ax == t.bx) {
      // Hypotenuse along a row or a column; c half its length away.
      const int mx = (t.ax + t.bx) / 2, my = (t.ay + t.by) / 2;
      const int half = (std::abs(t.bx - t.ax) + std::abs(t.by - t.ay)) / 2;
      if (t.ay == t.by) {
        const int step = t.cy > my ? 1 : -1;
        for (int k = 0; k <= half; ++k)
          f(my + step * k, mx - (half - k), mx + (half - k));
      } else {
        const bool east = t.cx > mx;
        for (int y = my - half; y <= my + half; ++y) {
          const int reach = half - std::abs(y - my);
          f(y, east ? mx : mx - reach, east ? mx + reach : mx);
        }
      }
      return;
    }
    // Legs along a row and a column from c.
    const int leg = std::max(std::abs(t.ax - t.cx), std::abs(t.ay - t.cy));
    const bool east = std::max(t.ax, t.bx) > t.cx;
    const int step = std::max(t.ay, t.by) > t.cy ? 1 : -1;
    for (int k = 0; k <= leg; ++k) {
      const int reach = leg - k;
      f(t.cy + step * k, east ? t.cx : t.cx - reach, east ? t.cx + reach : t.cx);
    }
  }

  /// The largest vertical distance of a sample in t (edges included) from t's plane, or some
  /// value above `stopAbove` as soon as one is found.
  double deviation(const Triangle& t, double stopAbove) const {
    const double ha = height(t.ax, t.ay), hb = height(t.bx, t.by), hc = height(t.cx, t.cy);
    const int ux = t.bx - t.ax, uy = t.by - t.ay, vx = t.cx - t.ax, vy = t.cy - t.ay;
    const double uh = hb - ha, vh = hc - ha;
    const int nz = ux * vy - uy * vx;
    const double gx = (uh * vy - uy * vh) / nz; // dh/dx
    const double gy = (ux * vh - uh * vx) / nz; // dh/dy
    double worst = 0.0;
    bool stop = false;
    forEachRow(t, [&](int y, int low, int high) {
      if (stop)
        return;
      const double rowPlane = ha + gy * (y - t.ay) - gx * t.ax;
      const double* row =
          &grid_.heights[static_cast<std::size_t>(y) * static_cast<std::size_t>(n_)];
      for (int x = low; x <= high; ++x)
        worst = std::max(worst, std::fabs(row[x] - (rowPlane + gx * x)));
      stop = worst > stopAbove;
    });
    return worst;
  }

  void emit(const Triangle& t, int depth, Mesh& mesh) {
    if (depth < splittableDepths_ && keep((t.ax + t.bx) / 2, (t.ay + t.by) / 2)) {
      emit(firstChild(t), depth + 1, mesh);
      emit(secondChild(t), depth + 1, mesh);
      return;
    }
    mesh.maxError = std::max(mesh.maxError, deviation(t, std::numeric_limits<double>::infinity()));
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
  std::vector<double> bound_;
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
