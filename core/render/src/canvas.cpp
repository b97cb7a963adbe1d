#include "strahler/render/canvas.h"

#include "strahler/geometry/distance.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace strahler::render {

using geometry::Vec2;

Canvas::Canvas(const geometry::Aabb& view, int longSide, Colour background) : view_(view) {
  const Vec2 size = view.size();
  scale_ = double(longSide) / std::max({size.x, size.y, 1e-9});
  image_.width = std::max(1, static_cast<int>(std::lround(size.x * scale_)));
  image_.height = std::max(1, static_cast<int>(std::lround(size.y * scale_)));
  image_.pixels.resize(static_cast<std::size_t>(image_.width) * image_.height * 3);
  for (std::size_t i = 0; i < image_.pixels.size(); i += 3)
    std::copy(background.begin(), background.end(),
              image_.pixels.begin() + static_cast<std::ptrdiff_t>(i));
}

Vec2 Canvas::toPixel(Vec2 p) const noexcept {
  return {(p.x - view_.min.x) * scale_, (view_.max.y - p.y) * scale_};
}

void Canvas::blendPixel(int x, int y, Colour colour, double alpha) noexcept {
  if (x < 0 || y < 0 || x >= image_.width || y >= image_.height || alpha <= 0.0)
    return;
  const std::size_t i =
      (static_cast<std::size_t>(y) * image_.width + static_cast<std::size_t>(x)) * 3;
  alpha = std::min(alpha, 1.0);
  for (std::size_t c = 0; c < 3; ++c)
    image_.pixels[i + c] = static_cast<std::uint8_t>(
        std::lround(image_.pixels[i + c] * (1.0 - alpha) + colour[c] * alpha));
}

void Canvas::fillPolygon(const geometry::Polygon& polygon, Colour colour) {
  std::vector<std::vector<Vec2>> rings;
  rings.reserve(polygon.holes.size() + 1);
  auto project = [&](const geometry::Ring& r) {
    std::vector<Vec2> out;
    out.reserve(r.size());
    for (Vec2 p : r)
      out.push_back(toPixel(p));
    rings.push_back(std::move(out));
  };
  project(polygon.outer);
  for (const geometry::Ring& h : polygon.holes)
    project(h);
  geometry::Aabb box;
  for (const auto& r : rings)
    for (Vec2 p : r)
      box.add(p);
  if (box.empty())
    return;
  const int y0 = std::max(0, static_cast<int>(std::floor(box.min.y)));
  const int y1 = std::min(image_.height - 1, static_cast<int>(std::ceil(box.max.y)));
  std::vector<double> crossings;
  for (int y = y0; y <= y1; ++y) {
    const double sy = y + 0.5;
    crossings.clear();
    for (const auto& r : rings)
      for (std::size_t i = 0, j = r.size() - 1; i < r.size(); j = i++)
        if ((r[i].y > sy) != (r[j].y > sy))
          crossings.push_back(r[i].x + (sy - r[i].y) / (r[j].y - r[i].y) * (r[j].x - r[i].x));
    std::sort(crossings.begin(), crossings.end());
    for (std::size_t k = 0; k + 1 < crossings.size(); k += 2) {
      const int xa = std::max(0, static_cast<int>(std::ceil(crossings[k] - 0.5)));
      const int xb =
          std::min(image_.width - 1, static_cast<int>(std::floor(crossings[k + 1] - 0.5)));
      for (int x = xa; x <= xb; ++x)
        blendPixel(x, y, colour, 1.0);
    }
  }
}

void Canvas::strokeRing(const geometry::Ring& ring, Colour colour, double widthPx) {
  for (std::size_t i = 0; i < ring.size(); ++i)
    drawLine(ring[i], ring[(i + 1) % ring.size()], widthPx, colour);
}

void Canvas::drawLine(Vec2 a, Vec2 b, double widthPx, Colour colour) {
  const Vec2 pa = toPixel(a), pb = toPixel(b);
  const double half = 0.5 * widthPx;
  const int x0 = std::max(0, static_cast<int>(std::floor(std::min(pa.x, pb.x) - half - 1)));
  const int x1 =
      std::min(image_.width - 1, static_cast<int>(std::ceil(std::max(pa.x, pb.x) + half + 1)));
  const int y0 = std::max(0, static_cast<int>(std::floor(std::min(pa.y, pb.y) - half - 1)));
  const int y1 =
      std::min(image_.height - 1, static_cast<int>(std::ceil(std::max(pa.y, pb.y) + half + 1)));
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      const double d = geometry::pointSegmentDistance({x + 0.5, y + 0.5}, pa, pb);
      blendPixel(x, y, colour, half + 0.5 - d); // one-pixel antialiased edge
    }
}

void Canvas::drawDot(Vec2 centre, double radiusPx, Colour colour) {
  drawLine(centre, centre, 2.0 * radiusPx, colour);
}

} // namespace strahler::render
