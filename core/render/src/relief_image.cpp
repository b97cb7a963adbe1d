#include "strahler/render/relief_image.h"

#include "strahler/render/canvas.h"

#include <algorithm>
#include <cmath>
#include <thread>
#include <vector>

namespace strahler::render {
namespace {

using geometry::Vec2;

struct Stop {
  double h;
  Colour c;
};

Colour tint(double h) {
  static constexpr Stop kLand[] = {{0, {92, 140, 78}},      {150, {132, 166, 92}},
                                   {400, {196, 186, 122}},  {800, {160, 122, 86}},
                                   {1400, {140, 130, 124}}, {2200, {240, 240, 240}}};
  if (h < 0.0) {
    const double t = std::clamp(-h / 120.0, 0.0, 1.0);
    return {static_cast<std::uint8_t>(70 - 40 * t), static_cast<std::uint8_t>(130 - 70 * t),
            static_cast<std::uint8_t>(190 - 70 * t)};
  }
  for (std::size_t i = 1; i < std::size(kLand); ++i)
    if (h <= kLand[i].h) {
      const double t = (h - kLand[i - 1].h) / (kLand[i].h - kLand[i - 1].h);
      Colour c;
      for (std::size_t k = 0; k < 3; ++k)
        c[k] =
            static_cast<std::uint8_t>(kLand[i - 1].c[k] + t * (kLand[i].c[k] - kLand[i - 1].c[k]));
      return c;
    }
  return std::end(kLand)[-1].c;
}

} // namespace

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

  const Vec2 light = normalize(Vec2{-1.0, 1.0}); // from the north-west
  for (int y = 0; y < hgt; ++y)
    for (int x = 0; x < w; ++x) {
      const double h = at(x, y);
      const double dx = (at(x + 1, y) - at(x - 1, y)) / (2 * pixel);
      const double dy = (at(x, y - 1) - at(x, y + 1)) / (2 * pixel); // y up
      const double exaggeration = 2.0;
      const double nx = -dx * exaggeration, ny = -dy * exaggeration;
      const double shade = std::clamp((nx * light.x + ny * light.y + 1.0) /
                                          std::sqrt(nx * nx + ny * ny + 1.0) * 0.75,
                                      0.0, 1.2);
      Colour c = tint(h);
      const std::size_t i = (static_cast<std::size_t>(y) * w + static_cast<std::size_t>(x)) * 3;
      const double s = h < 0.0 ? 1.0 : shade;
      for (std::size_t k = 0; k < 3; ++k)
        img.pixels[i + k] = static_cast<std::uint8_t>(std::clamp(c[k] * s, 0.0, 255.0));
    }
  Canvas rivers(view, longSide, {0, 0, 0});
  rivers.setImage(std::move(img));
  const auto& nodes = world.data().network.nodes;
  for (const primitives::RiverPrimitive& r : world.data().rivers) {
    const double width = 0.6 + 0.5 * (nodes[r.node.index()].strahler - 1);
    for (std::size_t k = 0; k + 1 < r.curve.size(); ++k)
      rivers.drawLine(r.curve[k].position, r.curve[k + 1].position, width, {40, 90, 200});
  }
  return rivers.image();
}

} // namespace strahler::render
