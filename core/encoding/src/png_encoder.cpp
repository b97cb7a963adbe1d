// The only translation unit that includes libspng: its error codes become base::Error here.
#include "png_encoder.h"

#include "strahler/base/guarded.h"

#include <cstddef>
#include <exception>
#include <memory>
#include <new>
#include <spng.h>

namespace strahler::encoding::detail {
namespace {

using base::ErrorCode;
using base::makeError;

struct ContextDeleter {
  void operator()(spng_ctx* context) const noexcept { spng_ctx_free(context); }
};
using Context = std::unique_ptr<spng_ctx, ContextDeleter>;

std::size_t bytesPerPixel(PngLayout layout) {
  switch (layout) {
  case PngLayout::kRgb8:
    return 3u;
  case PngLayout::kRgba8:
    return 4u;
  case PngLayout::kGray8:
    return 1u;
  case PngLayout::kGray16:
    break;
  }
  return 2u;
}

int filterChoice(PngFilter filter) {
  switch (filter) {
  case PngFilter::kNone:
    return SPNG_FILTER_CHOICE_NONE;
  case PngFilter::kSub:
    return SPNG_FILTER_CHOICE_SUB;
  case PngFilter::kUp:
    return SPNG_FILTER_CHOICE_UP;
  case PngFilter::kAverage:
    return SPNG_FILTER_CHOICE_AVG;
  case PngFilter::kPaeth:
    return SPNG_FILTER_CHOICE_PAETH;
  case PngFilter::kAdaptive:
    return SPNG_FILTER_CHOICE_ALL;
  }
  return SPNG_FILTER_CHOICE_ALL;
}

/// zlib.h's values; spelled out so that this file does not need zlib's header.
int zlibStrategy(ZlibStrategy strategy) {
  switch (strategy) {
  case ZlibStrategy::kDefault:
    return 0;
  case ZlibStrategy::kFiltered:
    return 1;
  case ZlibStrategy::kHuffmanOnly:
    return 2;
  case ZlibStrategy::kRle:
    return 3;
  }
  return 0;
}

/// libspng's write callback: appends to the std::string behind `user`. It must not throw
/// through C frames, so allocation failure becomes SPNG_IO_ERROR.
int appendToString(spng_ctx* /*context*/, void* user, void* data, std::size_t length) {
  try {
    static_cast<std::string*>(user)->append(static_cast<const char*>(data), length);
    return 0;
  } catch (...) {
    return SPNG_IO_ERROR;
  }
}

base::Error spngError(const char* step, int code) {
  return makeError(ErrorCode::kInternal, std::string("png encoder: ") + step +
                                             " failed: " + spng_strerror(code) + " (libspng " +
                                             std::to_string(code) + ")");
}

base::Status configure(spng_ctx* context, const PngOptions& options, std::string* out) {
  if (const int rc = spng_set_png_stream(context, appendToString, out); rc != 0)
    return spngError("setting the output stream", rc);
  if (const int rc = spng_set_option(context, SPNG_IMG_COMPRESSION_LEVEL, options.compressionLevel);
      rc != 0)
    return spngError("setting the compression level", rc);
  if (const int rc = spng_set_option(context, SPNG_FILTER_CHOICE, filterChoice(options.filter));
      rc != 0)
    return spngError("setting the filter", rc);
  if (const int rc =
          spng_set_option(context, SPNG_IMG_COMPRESSION_STRATEGY, zlibStrategy(options.strategy));
      rc != 0)
    return spngError("setting the zlib strategy", rc);
  return base::Ok{};
}

spng_ihdr headerFor(int width, int height, PngLayout layout) {
  spng_ihdr header{};
  header.width = static_cast<std::uint32_t>(width);
  header.height = static_cast<std::uint32_t>(height);
  header.bit_depth = layout == PngLayout::kGray16 ? 16 : 8;
  header.color_type = layout == PngLayout::kRgb8    ? SPNG_COLOR_TYPE_TRUECOLOR
                      : layout == PngLayout::kRgba8 ? SPNG_COLOR_TYPE_TRUECOLOR_ALPHA
                                                    : SPNG_COLOR_TYPE_GRAYSCALE;
  return header;
}

base::Result<std::string> encodeUnguarded(const std::vector<std::uint8_t>& samples, int width,
                                          int height, PngLayout layout, const PngOptions& options) {
  const Context context(spng_ctx_new(SPNG_CTX_ENCODER));
  if (!context)
    return makeError(ErrorCode::kInternal, "png encoder: cannot create a libspng context");
  std::string out;
  // Filtered, compressed tiles are far smaller than the raw samples; a quarter avoids most
  // regrowth without holding much memory.
  out.reserve(samples.size() / 4 + 1024);
  STRAHLER_RETURN_IF_ERROR(configure(context.get(), options, &out));
  spng_ihdr header = headerFor(width, height, layout);
  if (const int rc = spng_set_ihdr(context.get(), &header); rc != 0)
    return spngError("setting the image header", rc);
  // SPNG_FMT_RAW: 16-bit samples are already big-endian, as PNG stores them.
  if (const int rc = spng_encode_image(context.get(), samples.data(), samples.size(), SPNG_FMT_RAW,
                                       SPNG_ENCODE_FINALIZE);
      rc != 0)
    return spngError("encoding the image", rc);
  // Tiles are kept (tile cache) long after encoding: hand back exactly the bytes, not the
  // reservation (a 256² sea tile is ~1.5 KB of a 50 KB buffer).
  out.shrink_to_fit();
  return out;
}

/// The callers' side of the contract: a programmer error, not user input, when broken.
void assertShape(const std::vector<std::uint8_t>& samples, int width, int height,
                 PngLayout layout) {
  STRAHLER_ASSERT(width > 0 && height > 0, "PNG samples: empty image");
  STRAHLER_ASSERT(samples.size() == static_cast<std::size_t>(width) *
                                        static_cast<std::size_t>(height) * bytesPerPixel(layout),
                  "PNG samples: sample count does not match the image size");
}

/// Threshold between the two regimes measured on 256² Terrain-RGB tiles (level 1, Up filter,
/// one core; strahler_encoding_bench and its terrain kinds):
///   share ≈ 0.5  (2 m smooth hills, sea shelf): default 0.6–0.8 ms, 18–22 KiB;
///                Z_RLE 0.8–0.9 ms, 27–35 KiB.
///   share ≈ 0.42 (10 m hills): default 1.2 ms, 40 KiB; Z_RLE 1.0 ms, 60 KiB.
///   share ≈ 0.23 (smooth hills + 0.1 m noise): both ≈ 1.1 ms and 38 KiB.
///   share < 0.05 (30 m hills with pixel noise, 100 m+ hills): default 2.0–2.6 ms, 86–130 KiB;
///                Z_RLE 1.2–1.5 ms and 1–7 % smaller (LZ77 finds nothing, RLE wastes no time).
constexpr double kPredictableShare = 0.3;
/// Rows sampled for predictableShare(): every 4th is plenty and keeps it under 50 µs.
constexpr int kShareRowStep = 4;

} // namespace

double predictableShare(const std::vector<std::uint8_t>& samples, int width, int height,
                        PngLayout layout) {
  assertShape(samples, width, height, layout);
  const std::size_t bpp = bytesPerPixel(layout);
  const auto rowBytes = static_cast<std::size_t>(width) * bpp;
  std::size_t repeats = 0;
  std::size_t pixels = 0;
  for (int y = 0; y < height && width >= 3; y += kShareRowStep) {
    const std::uint8_t* row = samples.data() + static_cast<std::size_t>(y) * rowBytes;
    for (std::size_t i = 2 * bpp; i < rowBytes; i += bpp) {
      bool same = true;
      for (std::size_t b = i; b < i + bpp; ++b)
        same &= static_cast<std::uint8_t>(row[b] - row[b - bpp]) ==
                static_cast<std::uint8_t>(row[b - bpp] - row[b - 2 * bpp]);
      repeats += same ? 1 : 0;
      ++pixels;
    }
  }
  return pixels == 0 ? 0.0 : static_cast<double>(repeats) / static_cast<double>(pixels);
}

PngOptions choosePngOptions(const std::vector<std::uint8_t>& samples, int width, int height,
                            PngLayout layout) {
  const bool smooth = predictableShare(samples, width, height, layout) >= kPredictableShare;
  return {1, PngFilter::kUp, smooth ? ZlibStrategy::kDefault : ZlibStrategy::kRle};
}

base::Result<std::string> encodePng(const std::vector<std::uint8_t>& samples, int width, int height,
                                    PngLayout layout) {
  return encodePng(samples, width, height, layout,
                   choosePngOptions(samples, width, height, layout));
}

base::Result<std::string> encodePng(const std::vector<std::uint8_t>& samples, int width, int height,
                                    PngLayout layout, const PngOptions& options) {
  assertShape(samples, width, height, layout);
  return base::guarded({.label = "png encoder", .failurePrefix = ""},
                       [&] { return encodeUnguarded(samples, width, height, layout, options); });
}

} // namespace strahler::encoding::detail
