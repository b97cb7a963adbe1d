#include "strahler/quality/dem_file.h"

#include "strahler/base/guarded.h"
#include "strahler/image/image.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace strahler::quality {
namespace {

using base::ErrorCode;
using base::makeError;

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char ch) { return char(std::tolower(ch)); });
  return out;
}

bool isHeaderKey(const std::string& key) {
  static const char* const kKeys[] = {"ncols",     "nrows",     "xllcorner", "xllcenter",
                                      "yllcorner", "yllcenter", "cellsize",  "nodata_value"};
  return std::any_of(std::begin(kKeys), std::end(kKeys), [&](const char* k) { return key == k; });
}

/// Splits a line into whitespace-separated tokens (a trailing '\r' included in whitespace).
std::vector<std::string_view> tokenize(std::string_view line) {
  std::vector<std::string_view> tokens;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i])))
      ++i;
    const std::size_t start = i;
    while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i])))
      ++i;
    if (i > start)
      tokens.push_back(line.substr(start, i - start));
  }
  return tokens;
}

/// Parses a whole token as a double (from_chars: no locale, "nan"/"inf" parse and are then
/// refused by the callers as not finite).
std::optional<double> parseNumber(std::string_view token) {
  double value = 0;
  const char* end = token.data() + token.size();
  const char* begin = token.data() + (token.size() > 1 && token[0] == '+' ? 1 : 0);
  const auto [ptr, ec] = std::from_chars(begin, end, value);
  if (ec != std::errc() || ptr != end)
    return std::nullopt;
  return value;
}

/// Reads ESRI ASCII grids line by line, with the file and line in every message.
class AsciiGridReader {
public:
  explicit AsciiGridReader(std::string path) : path_(std::move(path)) {}

  base::Result<HeightRaster> read() {
    STRAHLER_RETURN_IF_ERROR(open());
    STRAHLER_RETURN_IF_ERROR(readHeader());
    STRAHLER_RETURN_IF_ERROR(checkHeader());
    return readValues();
  }

private:
  base::Error error(ErrorCode code, const std::string& what) const {
    return makeError(code, "dem '" + path_ + "' line " + std::to_string(line_) + ": " + what);
  }

  base::Status open() {
    std::error_code ec;
    if (!std::filesystem::exists(path_, ec))
      return makeError(ErrorCode::kNotFound, "dem '" + path_ + "': file not found");
    if (std::filesystem::is_directory(path_, ec))
      return makeError(ErrorCode::kIoError, "dem '" + path_ + "': is a directory");
    in_.open(path_, std::ios::binary);
    if (!in_)
      return makeError(ErrorCode::kIoError, "dem '" + path_ + "': cannot open");
    return base::Ok{};
  }

  /// Next non-empty line's tokens into tokens_; false at the end of the file.
  bool nextLine() {
    while (std::getline(in_, text_)) {
      ++line_;
      tokens_ = tokenize(text_);
      if (!tokens_.empty())
        return true;
    }
    tokens_.clear();
    return false;
  }

  base::Status readHeader() {
    while (nextLine()) {
      const std::string key = lower(tokens_[0]);
      if (parseNumber(tokens_[0]))
        return base::Ok{}; // first row of values
      if (!isHeaderKey(key))
        return error(ErrorCode::kInvalidInput, "unknown header key '" + std::string(tokens_[0]) +
                                                   "' (or a value that is not a number)");
      if (tokens_.size() != 2)
        return error(ErrorCode::kInvalidInput,
                     "header key '" + std::string(tokens_[0]) + "' needs exactly one value");
      if (header_.count(key))
        return error(ErrorCode::kInvalidInput, "header key '" + key + "' given twice");
      const auto value = parseNumber(tokens_[1]);
      if (!value || !std::isfinite(*value))
        return error(ErrorCode::kInvalidInput, "header value '" + std::string(tokens_[1]) +
                                                   "' of '" + key + "' is not a finite number");
      header_[key] = *value;
      keyLine_[key] = line_;
    }
    return error(ErrorCode::kInvalidInput, "the file ends before the first value");
  }

  base::Status checkHeader() {
    // Missing keys are reported at the first value, others at their own line.
    const int firstValueLine = line_;
    for (const char* key : {"ncols", "nrows", "cellsize"})
      if (!header_.count(key))
        return error(ErrorCode::kInvalidInput,
                     std::string("the header ends here without '") + key + "'");
    for (const char* axis : {"x", "y"}) {
      const std::string corner = std::string(axis) + "llcorner";
      const std::string center = std::string(axis) + "llcenter";
      if (header_.count(corner) == header_.count(center))
        return error(ErrorCode::kInvalidInput,
                     "the header needs exactly one of '" + corner + "' and '" + center + "'");
    }
    for (const char* key : {"ncols", "nrows"}) {
      const double v = header_[key];
      line_ = keyLine_[key];
      if (v < 1 || v != std::floor(v) || v > 1e9)
        return error(ErrorCode::kInvalidInput,
                     std::string("'") + key + "' must be a positive integer, not " + number(v));
    }
    line_ = keyLine_["cellsize"];
    if (!(header_["cellsize"] > 0))
      return error(ErrorCode::kInvalidInput,
                   "'cellsize' must be positive, not " + number(header_["cellsize"]));
    line_ = keyLine_["nrows"];
    const double cells = header_["ncols"] * header_["nrows"];
    if (cells > double(kMaxDemCells))
      return error(ErrorCode::kLimitExceeded,
                   number(header_["ncols"]) + " x " + number(header_["nrows"]) +
                       " cells is more than the limit of " + std::to_string(kMaxDemCells));
    line_ = firstValueLine;
    return base::Ok{};
  }

  static std::string number(double v) {
    char buffer[32];
    const auto [ptr, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
    return ec == std::errc() ? std::string(buffer, ptr) : std::string("?");
  }

  HeightRaster emptyRaster() {
    HeightRaster r;
    r.width = int(header_["ncols"]);
    r.height = int(header_["nrows"]);
    r.cellSize = header_["cellsize"];
    const double half = 0.5 * r.cellSize;
    r.origin.x = header_.count("xllcenter") ? header_["xllcenter"] : header_["xllcorner"] + half;
    r.origin.y = header_.count("yllcenter") ? header_["yllcenter"] : header_["yllcorner"] + half;
    const std::size_t n = std::size_t(r.width) * std::size_t(r.height);
    r.heights.assign(n, 0.0f);
    r.cellClass.assign(n, std::uint8_t(CellClass::kLand));
    return r;
  }

  base::Result<HeightRaster> readValues() {
    HeightRaster r = emptyRaster();
    const std::size_t w = std::size_t(r.width), total = r.heights.size();
    const std::optional<double> nodata = header_.count("nodata_value")
                                             ? std::optional<double>(header_["nodata_value"])
                                             : std::nullopt;
    std::size_t k = 0;
    do {
      for (std::string_view token : tokens_) {
        if (k == total)
          return error(ErrorCode::kInvalidInput,
                       "more values than ncols x nrows = " + std::to_string(total));
        const auto value = parseNumber(token);
        if (!value || !std::isfinite(*value) || std::fabs(*value) > 1e30)
          return error(ErrorCode::kInvalidInput,
                       "value " + std::to_string(k + 1) + " ('" + std::string(token) + "', row " +
                           std::to_string(k / w + 1) + " column " + std::to_string(k % w + 1) +
                           ") is not a finite number");
        // Row 0 of the file is the north row; the raster's row 0 is the south row.
        const std::size_t i = (std::size_t(r.height) - 1 - k / w) * w + k % w;
        if (nodata && *value == *nodata)
          r.cellClass[i] = std::uint8_t(CellClass::kSea);
        else
          r.heights[i] = float(*value);
        ++k;
      }
    } while (nextLine());
    if (k != total)
      return error(ErrorCode::kInvalidInput,
                   "the file ends after " + std::to_string(k) +
                       " values; ncols x nrows = " + std::to_string(total));
    return r;
  }

  std::string path_;
  std::ifstream in_;
  std::string text_;
  std::vector<std::string_view> tokens_;
  int line_ = 0;
  std::map<std::string, double> header_;
  std::map<std::string, int> keyLine_;
};

/// True when the file's first word is an ESRI ASCII header key.
bool looksLikeAsciiGrid(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string word;
  if (!(in >> word))
    return false;
  return isHeaderKey(lower(word));
}

/// A raster OpenImageIO reads (top row first) as a HeightRaster of land cells.
base::Result<HeightRaster> readImageDem(const std::string& path, double cellSize) {
  STRAHLER_ASSIGN_OR_RETURN(image::GrayImage image, image::readFloatRaster(path, kMaxDemCells));
  HeightRaster r;
  r.width = image.width;
  r.height = image.height;
  r.cellSize = cellSize;
  r.origin = {0.5 * cellSize, 0.5 * cellSize};
  const std::size_t w = std::size_t(r.width);
  r.heights.resize(image.pixels.size());
  r.cellClass.assign(image.pixels.size(), std::uint8_t(CellClass::kLand));
  for (std::size_t y = 0; y < std::size_t(r.height); ++y)
    std::copy_n(image.pixels.begin() + std::ptrdiff_t(y * w), w,
                r.heights.begin() + std::ptrdiff_t((std::size_t(r.height) - 1 - y) * w));
  return r;
}

/// Metres per degree of latitude (blind_set.py's EARTH / 360).
constexpr double kMetresPerDegree = 40075016.686 / 360.0;

} // namespace

HeightRaster squareDegreeCells(const HeightRaster& grid) {
  const double half = 0.5 * grid.cellSize;
  const double latitude = grid.origin.y - half + grid.cellSize * grid.height / 2.0;
  const double dy = grid.cellSize * kMetresPerDegree;
  const double zoom = std::cos(latitude * 0.017453292519943295); // dx / dy
  HeightRaster r;
  r.width = std::max(1, int(std::nearbyint(grid.width * zoom))); // numpy rounds half to even
  r.height = grid.height;
  r.cellSize = dy;
  r.origin = {(grid.origin.x - half) * dy * zoom / grid.cellSize + 0.5 * dy,
              (grid.origin.y - half) * kMetresPerDegree + 0.5 * dy};
  const std::size_t w = std::size_t(r.width), gw = std::size_t(grid.width);
  r.heights.resize(w * std::size_t(r.height));
  r.cellClass.resize(r.heights.size());
  // scipy.ndimage.zoom's mapping: output column j samples input column j·(in − 1)/(out − 1);
  // heights linearly (order 1), the cell's class from the nearest column (order 0).
  const double scale = r.width > 1 ? double(grid.width - 1) / double(r.width - 1) : 0.0;
  for (std::size_t j = 0; j < w; ++j) {
    const double at = double(j) * scale;
    const std::size_t left = std::min(std::size_t(at), gw - 1), right = std::min(left + 1, gw - 1);
    const double t = at - double(left);
    const std::size_t nearest = std::min(std::size_t(std::floor(at + 0.5)), gw - 1);
    for (std::size_t y = 0; y < std::size_t(r.height); ++y) {
      const std::size_t row = y * gw;
      r.heights[y * w + j] = float((1.0 - t) * double(grid.heights[row + left]) +
                                   t * double(grid.heights[row + right]));
      r.cellClass[y * w + j] = grid.cellClass[row + nearest];
    }
  }
  return r;
}

base::Result<HeightRaster> readEsriAsciiGrid(const std::string& path) {
  const std::string label = "dem '" + path + "'";
  return base::guarded(label, [&] { return AsciiGridReader(path).read(); });
}

base::Result<HeightRaster> readDemFile(const std::string& path, std::optional<double> cellSize) {
  if (cellSize && !(*cellSize > 0 && std::isfinite(*cellSize)))
    return makeError(ErrorCode::kOutOfRange, "dem cell size must be a positive number of metres");
  std::error_code ec;
  if (!std::filesystem::exists(path, ec))
    return makeError(ErrorCode::kNotFound, "dem '" + path + "': file not found");
  if (looksLikeAsciiGrid(path)) {
    STRAHLER_ASSIGN_OR_RETURN(HeightRaster r, readEsriAsciiGrid(path));
    if (cellSize)
      r.cellSize = *cellSize;
    else if (r.cellSize < kDegreeCellLimit)
      return squareDegreeCells(r);
    return r;
  }
  if (!cellSize)
    return makeError(ErrorCode::kInvalidInput,
                     "dem '" + path +
                         "': not an ESRI ASCII grid, and an image raster needs --cell-size");
  return readImageDem(path, *cellSize);
}

} // namespace strahler::quality
