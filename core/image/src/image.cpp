// The image API. The functions that need OpenImageIO run in its module (oiio_module.cpp),
// loaded on their first call: a program that never reads an image file nor writes a float
// TIFF/EXR or a PNG picture never loads OpenImageIO's ~250 libraries.
#include "strahler/image/image.h"

#include "oiio_module.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <system_error>

namespace strahler::image {
namespace {

using base::ErrorCode;
using base::makeError;

using detail::quoted;

/// The module, or its loading error prefixed with `label` (what the caller was doing).
base::Result<const detail::OiioModule*> moduleFor(const std::string& label) {
  const base::Result<const detail::OiioModule*>& module = detail::oiioModule();
  if (!module)
    return makeError(module.error().code, label + ": " + module.error().message);
  return module.value();
}

/// Missing files and folders are told apart here, before any image library is involved.
base::Status checkReadable(const std::string& path, const std::string& label) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (status.type() == std::filesystem::file_type::not_found)
    return makeError(ErrorCode::kNotFound, label + ": file not found");
  if (ec)
    return makeError(ErrorCode::kIoError, label + ": " + ec.message());
  if (std::filesystem::is_directory(status))
    return makeError(ErrorCode::kIoError, label + ": is a directory");
  return base::Ok{};
}

const char* floatLabel(FloatImageFormat format) {
  return format == FloatImageFormat::kTiff ? "float TIFF" : "float EXR";
}

} // namespace

float GrayImage::at(int x, int y) const noexcept {
  if (width <= 0 || height <= 0 ||
      pixels.size() < static_cast<std::size_t>(width) * static_cast<std::size_t>(height))
    return 0.0f;
  const auto cx = static_cast<std::size_t>(std::clamp(x, 0, width - 1));
  const auto cy = static_cast<std::size_t>(std::clamp(y, 0, height - 1));
  return pixels[cy * static_cast<std::size_t>(width) + cx];
}

float GrayImage::sample(double u, double v) const noexcept {
  // Pixel centres sit at (i + 0.5) / width: the image covers [0, 1]² edge to edge.
  const double cu = u >= 0.0 ? std::min(u, 1.0) : 0.0; // also maps NaN to 0
  const double cv = v >= 0.0 ? std::min(v, 1.0) : 0.0;
  const double fx = cu * width - 0.5;
  const double fy = cv * height - 0.5;
  const double x0 = std::floor(fx);
  const double y0 = std::floor(fy);
  const double tx = fx - x0;
  const double ty = fy - y0;
  const int ix = static_cast<int>(x0);
  const int iy = static_cast<int>(y0);
  const double top = at(ix, iy) * (1.0 - tx) + at(ix + 1, iy) * tx;
  const double bottom = at(ix, iy + 1) * (1.0 - tx) + at(ix + 1, iy + 1) * tx;
  return static_cast<float>(top * (1.0 - ty) + bottom * ty);
}

base::Result<GrayImage> readGrayImage(const std::string& path, std::size_t maxPixels) {
  const std::string label = "image " + quoted(path);
  STRAHLER_RETURN_IF_ERROR(checkReadable(path, label));
  STRAHLER_ASSIGN_OR_RETURN(const detail::OiioModule* module, moduleFor(label));
  return module->readGrayImage(path, maxPixels);
}

base::Result<GrayImage> readFloatRaster(const std::string& path, std::size_t maxPixels) {
  const std::string label = "raster " + quoted(path);
  STRAHLER_RETURN_IF_ERROR(checkReadable(path, label));
  STRAHLER_ASSIGN_OR_RETURN(const detail::OiioModule* module, moduleFor(label));
  return module->readFloatRaster(path, maxPixels);
}

base::Status writePng(const std::string& path, const RgbImage& image) {
  STRAHLER_ASSIGN_OR_RETURN(const detail::OiioModule* module, moduleFor("png " + quoted(path)));
  return module->writePng(path, image);
}

base::Result<std::string> encodeFloatImage(const std::vector<float>& pixels, int width, int height,
                                           FloatImageFormat format) {
  STRAHLER_ASSIGN_OR_RETURN(const detail::OiioModule* module, moduleFor(floatLabel(format)));
  return module->encodeFloatImage(pixels, width, height, format);
}

base::Result<GrayImage> decodeFloatImage(const std::string& bytes, FloatImageFormat format,
                                         std::size_t maxPixels) {
  STRAHLER_ASSIGN_OR_RETURN(const detail::OiioModule* module,
                            moduleFor(std::string(floatLabel(format)) + " in memory"));
  return module->decodeFloatImage(bytes, format, maxPixels);
}

} // namespace strahler::image
