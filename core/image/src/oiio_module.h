// The boundary between strahler::image and its OpenImageIO module, strahler_image_oiio.so.
// OpenImageIO pulls in ~250 shared libraries (GDAL, HDF5, OpenCV, FFmpeg, ...) whose loading
// costs ~0.5 s of CPU: linked into the program it would slow every start-up, so the module is
// loaded on first use (oiio_loader.cpp) and only image.cpp and oiio_module.cpp see this file.
#pragma once

#include "strahler/image/image.h"

#include <cstddef>
#include <string>
#include <vector>

#define STRAHLER_IMAGE_STRINGIFY_INNER(x) #x
#define STRAHLER_IMAGE_STRINGIFY(x) STRAHLER_IMAGE_STRINGIFY_INNER(x)

/// Identifies the interface and the C++ ABI it is passed through (compiler, standard library):
/// the loader refuses a module whose string differs. Bump the number when OiioModule, or a type
/// it passes, changes.
#define STRAHLER_IMAGE_OIIO_ABI                                                                    \
  "strahler_image_oiio 1; " __VERSION__ "; libstdc++ " STRAHLER_IMAGE_STRINGIFY(__GLIBCXX__)

namespace strahler::image::detail {

/// `path` in single quotes, as every image error message names its file.
inline std::string quoted(const std::string& path) {
  return "'" + path + "'";
}

/// The image functions that need OpenImageIO, with image.h's contracts. Every implementation
/// catches its own exceptions: none crosses the module boundary.
class OiioModule {
public:
  virtual base::Result<GrayImage> readGrayImage(const std::string& path,
                                                std::size_t maxPixels) const = 0;
  virtual base::Result<GrayImage> readFloatRaster(const std::string& path,
                                                  std::size_t maxPixels) const = 0;
  virtual base::Status writePng(const std::string& path, const RgbImage& image) const = 0;
  virtual base::Result<std::string> encodeFloatImage(const std::vector<float>& pixels, int width,
                                                     int height, FloatImageFormat format) const = 0;
  virtual base::Result<GrayImage> decodeFloatImage(const std::string& bytes,
                                                   FloatImageFormat format,
                                                   std::size_t maxPixels) const = 0;

protected:
  ~OiioModule() = default;
};

/// The module's file name (core/image/CMakeLists.txt builds it under this name).
inline constexpr const char* kOiioModuleFile = "strahler_image_oiio.so";
/// Its two entry points, `extern "C"` so that dlsym finds them by these names.
inline constexpr const char* kOiioAbiSymbol = "strahler_image_oiio_abi";
inline constexpr const char* kOiioModuleSymbol = "strahler_image_oiio_module";
using OiioAbiFunction = const char* (*)();
using OiioModuleFunction = const OiioModule* (*)();

/// The module, loaded (once per process, thread-safe) on the first call; or why it cannot be
/// loaded: kUnsupported with a message naming the module file and where it was looked for.
const base::Result<const OiioModule*>& oiioModule();

} // namespace strahler::image::detail
