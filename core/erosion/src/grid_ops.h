#pragma once

#include <algorithm>
#include <cstddef>
#include <span>
#include <thread>
#include <vector>

namespace strahler::erosion::detail {

/// The 8 neighbours (dx, dy) in a fixed order; the first four are the axis neighbours.
inline constexpr int kDx[8] = {1, -1, 0, 0, 1, -1, 1, -1};
inline constexpr int kDy[8] = {0, 0, 1, -1, 1, 1, -1, -1};

/// Threads to use: `threads`, or the hardware's when 0, never more than `rows`.
inline int threadCount(int threads, int rows) {
  int n = threads > 0 ? threads : static_cast<int>(std::thread::hardware_concurrency());
  return std::clamp(n, 1, std::max(1, rows));
}

/// Runs fn(y0, y1) on `threads` fixed bands of rows [0, rows). Each band writes only its rows.
template <class Fn> void forBands(int rows, int threads, Fn&& fn) {
  const int n = threadCount(threads, rows);
  if (n == 1) {
    fn(0, rows);
    return;
  }
  std::vector<std::thread> pool;
  pool.reserve(static_cast<std::size_t>(n));
  for (int b = 0; b < n; ++b) {
    const int y0 = rows * b / n;
    const int y1 = rows * (b + 1) / n;
    pool.emplace_back([&fn, y0, y1] { fn(y0, y1); });
  }
  for (std::thread& t : pool)
    t.join();
}

/// `src` (width × height) with `border` samples on every side, the edge samples repeated.
inline void extendEdges(std::span<const double> src, int width, int height, int border,
                        std::vector<double>& out) {
  const int w = width + 2 * border;
  out.resize(static_cast<std::size_t>(w) * static_cast<std::size_t>(height + 2 * border));
  for (int y = 0; y < height + 2 * border; ++y) {
    const int sy = std::clamp(y - border, 0, height - 1);
    for (int x = 0; x < w; ++x) {
      const int sx = std::clamp(x - border, 0, width - 1);
      out[static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x)] =
          src[static_cast<std::size_t>(sy) * static_cast<std::size_t>(width) +
              static_cast<std::size_t>(sx)];
    }
  }
}

} // namespace strahler::erosion::detail
