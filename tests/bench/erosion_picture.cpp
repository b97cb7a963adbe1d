// Writes docs/screenshots/erosion-before-after.png: the hillshade of a 1025² grid of Mallorca's
// Serra de Tramuntana before (left) and after (right) 50 rounds of the seed's erosion.
// Run: build/release/tests/bench/strahler_erosion_picture docs/screenshots/erosion-before-after.png
#include "erosion_grid.h"

#include "strahler/erosion/erosion.h"
#include "strahler/image/image.h"
#include "strahler/render/shaded_relief.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace {

constexpr int kSize = 1025;
constexpr double kSideM = 20480.0; // 20 m per sample.

/// The hillshaded colour relief of a grid (edges extended by one sample).
strahler::image::RgbImage shade(const std::vector<double>& h) {
  std::vector<double> bordered;
  bordered.reserve(static_cast<std::size_t>((kSize + 2) * (kSize + 2)));
  for (int y = -1; y <= kSize; ++y)
    for (int x = -1; x <= kSize; ++x)
      bordered.push_back(h[static_cast<std::size_t>(std::clamp(y, 0, kSize - 1) * kSize +
                                                    std::clamp(x, 0, kSize - 1))]);
  const std::vector<double> spacing(kSize + 2, kSideM / (kSize - 1));
  return strahler::render::shadeRelief(bordered, kSize, kSize, spacing);
}

} // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s OUT.png\n", argv[0]);
    return 1;
  }
  using namespace strahler;
  const std::vector<double> before =
      bench::mallorcaGrid(kSize, bench::kSerraLon, bench::kSerraLat, kSideM);
  auto eroded = erosion::erode(before, kSize, kSize, kSideM / (kSize - 1), erosion::Params{});
  if (!eroded.ok()) {
    std::fprintf(stderr, "%s\n", eroded.error().message.c_str());
    return 1;
  }
  const image::RgbImage left = shade(before);
  const image::RgbImage right = shade(eroded.value().surface());
  constexpr int kGap = 8;
  image::RgbImage out;
  out.width = 2 * kSize + kGap;
  out.height = kSize;
  out.pixels.assign(static_cast<std::size_t>(out.width * out.height * 3), 255);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      for (int c = 0; c < 3; ++c) {
        const std::size_t from = static_cast<std::size_t>((y * kSize + x) * 3 + c);
        out.pixels[static_cast<std::size_t>((y * out.width + x) * 3 + c)] = left.pixels[from];
        out.pixels[static_cast<std::size_t>((y * out.width + x + kSize + kGap) * 3 + c)] =
            right.pixels[from];
      }
  const auto status = image::writePng(argv[1], out);
  if (!status.ok()) {
    std::fprintf(stderr, "%s\n", status.error().message.c_str());
    return 1;
  }
  const std::vector<double> after = eroded.value().surface();
  double most = 0.0, total = 0.0, sediment = 0.0;
  for (std::size_t i = 0; i < after.size(); ++i) {
    most = std::max(most, std::abs(after[i] - before[i]));
    total += std::abs(after[i] - before[i]);
    sediment = std::max(sediment, eroded.value().sediment[i]);
  }
  std::printf("stable %d after %d final sweeps; |change| max %.2f m, mean %.3f m; deepest "
              "sediment %.2f m\n",
              eroded.value().stable ? 1 : 0, eroded.value().finalSweeps, most,
              total / static_cast<double>(after.size()), sediment);
  return 0;
}
