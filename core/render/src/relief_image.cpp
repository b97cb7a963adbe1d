#include "strahler/render/relief_image.h"

#include "strahler/render/canvas.h"
#include "strahler/render/shaded_relief.h"

#include <algorithm>
#include <cmath>
#include <thread>
#include <vector>

namespace strahler::render {
using geometry::Vec2;

image::RgbImage drawReliefImage(const construction::World& world, int longSide, int threads) {
  const geometry::Aabb land = world.land().bounds();
  const geometry::Aabb view = land.expanded(0.04 * std::max(land.size().x, land.size().y));
  Canvas canvas(view, longSide, {0, 0, 0});
  image::RgbImage img = canvas.image();
  const int w = img.width, hgt = img.height;
  const double pixel = view.size().x / w;
  // Heights on a grid one pixel larger on each side, for the shading gradient.
  std::vector<double> z(static_cast<std::size_t>(w + 2) * static_cast<std::size_t>(hgt + 2));
  auto at = [&](int x, int y) -> double& {
    return z[static_cast<std::size_t>(y + 1) * (w + 2) + (x + 1)];
  };
  auto rows = [&](int first, int step) {
    std::vector<Vec2> points(static_cast<std::size_t>(w + 2));
    for (int y = first - 1; y <= hgt; y += step) {
      for (int x = -1; x <= w; ++x)
        points[static_cast<std::size_t>(x + 1)] = {view.min.x + (x + 0.5) * pixel,
                                                   view.max.y - (y + 0.5) * pixel};
      world.heights(points, pixel, {&at(-1, y), points.size()});
    }
  };
  std::vector<std::thread> pool;
  const int n = std::max(1, threads);
  for (int t = 1; t < n; ++t)
    pool.emplace_back(rows, t, n);
  rows(0, n);
  for (std::thread& t : pool)
    t.join();

  // Every row of the bordered grid is `pixel` apart.
  image::RgbImage shaded =
      shadeRelief(z, w, hgt, std::vector<double>(static_cast<std::size_t>(hgt + 2), pixel));
  Canvas rivers(view, longSide, {0, 0, 0});
  rivers.setImage(std::move(shaded));
  const auto& nodes = world.data().network.nodes;
  for (const primitives::RiverPrimitive& r : world.data().rivers) {
    const double width = 0.6 + 0.5 * (nodes[r.node.index()].strahler - 1);
    for (std::size_t k = 0; k + 1 < r.curve.size(); ++k)
      rivers.drawLine(r.curve[k].position, r.curve[k + 1].position, width, {40, 90, 200});
  }
  return rivers.image();
}

} // namespace strahler::render
