#pragma once

// libspng behind a narrow, private interface: png_encoder.cpp is the only source of the
// library that includes spng.h (heightmap_encoder_test decodes with it). The benchmark
// (tests/bench/encoding_bench.cpp) and the unit tests include this header to compare
// settings; the heightmap encoders let choosePngOptions() pick.

#include "strahler/base/result.h"

#include <cstdint>
#include <string>
#include <vector>

namespace strahler::encoding::detail {

/// Pixel layouts the heightmap formats use.
enum class PngLayout {
  kRgb8,   ///< 3 bytes per pixel: R, G, B.
  kRgba8,  ///< 4 bytes per pixel: R, G, B, A (not premultiplied).
  kGray16, ///< 2 bytes per pixel, big-endian (PNG's own byte order).
  kGray8,  ///< 1 byte per pixel (the layer tiles' 8-bit grey).
};

/// PNG row filters (RFC 2083 §6); kAdaptive lets the encoder pick one per row.
enum class PngFilter { kNone, kSub, kUp, kAverage, kPaeth, kAdaptive };

/// zlib strategies (zlib.h: Z_DEFAULT_STRATEGY, Z_FILTERED, Z_HUFFMAN_ONLY, Z_RLE).
enum class ZlibStrategy { kDefault, kFiltered, kHuffmanOnly, kRle };

/// Compression settings for one image.
struct PngOptions {
  int compressionLevel = 1; ///< zlib level, 0 (store) .. 9 (smallest).
  PngFilter filter = PngFilter::kUp;
  ZlibStrategy strategy = ZlibStrategy::kDefault;
};

/// Share of pixels (sampled on every 4th row) whose byte-wise step from the left neighbour
/// repeats the previous pixel's step: high on smooth or flat tiles, where deflate's LZ77
/// matching pays, near 0 on rough or noisy ones. 0 for images narrower than 3 pixels.
double predictableShare(const std::vector<std::uint8_t>& samples, int width, int height,
                        PngLayout layout);

/// The settings measured best on 256² tiles (strahler_encoding_bench, see the comment in
/// png_encoder.cpp): zlib level 1 with the Up filter, zlib's default strategy when
/// predictableShare() ≥ 0.3, else Z_RLE.
PngOptions choosePngOptions(const std::vector<std::uint8_t>& samples, int width, int height,
                            PngLayout layout);

/// Encodes rows of `samples` (top row first, width · bytes-per-pixel bytes each, no filter
/// bytes) as an 8-bit RGB, 16-bit grey or 8-bit grey PNG with no ancillary chunks. The caller
/// guarantees 1 ≤ width, height and samples.size() = width · height · bytes-per-pixel (asserted);
/// libspng failures become kInternal. Deterministic for one zlib build.
base::Result<std::string> encodePng(const std::vector<std::uint8_t>& samples, int width, int height,
                                    PngLayout layout, const PngOptions& options);

/// encodePng with choosePngOptions().
base::Result<std::string> encodePng(const std::vector<std::uint8_t>& samples, int width, int height,
                                    PngLayout layout);

} // namespace strahler::encoding::detail
