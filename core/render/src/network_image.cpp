#include "strahler/render/network_image.h"

#include "strahler/base/random.h"
#include "strahler/geometry/polygon_index.h"
#include "strahler/render/canvas.h"

#include <algorithm>

namespace strahler::render {
namespace {

constexpr Colour kSea{28, 52, 84};
constexpr Colour kLake{60, 110, 160};
constexpr Colour kBlockEdge{150, 140, 120};
constexpr Colour kMouth{200, 40, 40};

/// A pale, distinct tint per watershed.
Colour watershedTint(std::uint32_t tree) {
  base::Rng rng(tree, 0x74696e74ull);
  return {static_cast<std::uint8_t>(170 + rng.below(70)),
          static_cast<std::uint8_t>(170 + rng.below(70)),
          static_cast<std::uint8_t>(140 + rng.below(60))};
}

Colour riverColour(analysis::RosgenType type) {
  switch (type) {
  case analysis::RosgenType::kStraight:
    return {20, 60, 170};
  case analysis::RosgenType::kSinuous:
    return {30, 110, 210};
  case analysis::RosgenType::kBraided:
    return {0, 160, 200};
  case analysis::RosgenType::kDelta:
    return {0, 190, 160};
  }
  return {0, 0, 0};
}

} // namespace

image::RgbImage drawNetworkImage(const geometry::MultiPolygon& land,
                                 const network::RiverNetwork& network,
                                 const blocks::BlockSet& blocks,
                                 const analysis::NetworkAnalysis& analysis, int longSide) {
  const geometry::Aabb box = geometry::bounds(land);
  Canvas canvas(box.expanded(0.03 * std::max(box.size().x, box.size().y)), longSide, kSea);
  for (const geometry::Polygon& p : land)
    canvas.fillPolygon({p.outer, {}}, kLake);
  for (std::size_t i = 0; i < blocks.blocks.size(); ++i) {
    const Colour tint = watershedTint(network.nodes[i].tree);
    for (const geometry::Polygon& piece : blocks.blocks[i].region)
      canvas.fillPolygon(piece, tint);
  }
  const double pixelsPerMetre = longSide / std::max(box.size().x, box.size().y);
  if (network.edgeLength * pixelsPerMetre > 4.0) {
    // Outline block borders on land only: clipped regions may carry zero-width bridges over water.
    const geometry::PolygonIndex landIndex(land);
    for (const blocks::Block& b : blocks.blocks)
      for (const geometry::Polygon& piece : b.region)
        for (std::size_t k = 0; k < piece.outer.size(); ++k) {
          const geometry::Vec2 a = piece.outer[k], c = piece.outer[(k + 1) % piece.outer.size()];
          const geometry::Vec2 mid = (a + c) * 0.5;
          if (landIndex.contains(mid) || landIndex.distanceToBoundary(mid, 1.0) < 0.5)
            canvas.drawLine(a, c, 0.6, kBlockEdge);
        }
  }
  for (const network::RiverNode& node : network.nodes) {
    if (!node.parent.valid())
      continue;
    const double width = 0.8 + 0.9 * (node.strahler - 1);
    const auto i = static_cast<std::size_t>(&node - network.nodes.data());
    canvas.drawLine(node.position, network.node(node.parent).position, width,
                    riverColour(analysis.rosgen[i]));
  }
  for (const network::Mouth& m : network.mouths)
    canvas.drawDot(network.node(m.node).position, 2.0, kMouth);
  return canvas.image();
}

} // namespace strahler::render
