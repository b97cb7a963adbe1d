#pragma once

#include "strahler/geometry/aabb.h"
#include "strahler/geometry/polygon.h"
#include "strahler/image/image.h"

#include <array>
#include <cstdint>

namespace strahler::render {

/// An 8-bit RGB colour.
using Colour = std::array<std::uint8_t, 3>;

/// A raster image that maps a rectangle of the local frame (metres, y up) onto pixels
/// (y down), with the few drawing primitives the inspection images need.
class Canvas {
public:
  /// A canvas showing `view`, `longSide` pixels along its longer side, filled with `background`.
  Canvas(const geometry::Aabb& view, int longSide, Colour background);

  /// Fills a multipolygon (even-odd, so holes stay empty).
  void fillPolygon(const geometry::Polygon& polygon, Colour colour);
  /// Draws the outline of a ring, one pixel wide.
  void strokeRing(const geometry::Ring& ring, Colour colour, double widthPx = 1.0);
  /// Draws a segment of the given width in pixels (round caps).
  void drawLine(geometry::Vec2 a, geometry::Vec2 b, double widthPx, Colour colour);
  /// Draws a filled disc of the given radius in pixels.
  void drawDot(geometry::Vec2 centre, double radiusPx, Colour colour);

  /// Replaces the pixels (same size as the canvas), e.g. to draw over a computed image.
  void setImage(image::RgbImage image) { image_ = std::move(image); }
  /// The pixels drawn so far.
  const image::RgbImage& image() const noexcept { return image_; }

private:
  geometry::Vec2 toPixel(geometry::Vec2 p) const noexcept;
  void blendPixel(int x, int y, Colour colour, double alpha) noexcept;

  geometry::Aabb view_;
  double scale_; // pixels per metre
  image::RgbImage image_;
};

} // namespace strahler::render
