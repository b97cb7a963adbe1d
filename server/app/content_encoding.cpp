#include "content_encoding.h"

#include "strahler/base/assert.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <limits>
#include <zlib.h>

namespace strahler::app {
namespace {

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t'))
    s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t'))
    s.remove_suffix(1);
  return s;
}

bool equalsLower(std::string_view s, std::string_view lower) {
  return s.size() == lower.size() &&
         std::equal(s.begin(), s.end(), lower.begin(), [](char a, char b) {
           return std::tolower(static_cast<unsigned char>(a)) == b;
         });
}

/// The q of one list member's parameters ("; q=0.5"); 1 without one, 0 when malformed.
double quality(std::string_view parameters) {
  while (!parameters.empty()) {
    const std::size_t semicolon = parameters.find(';');
    const std::string_view parameter = trimmed(parameters.substr(0, semicolon));
    parameters =
        semicolon == std::string_view::npos ? std::string_view{} : parameters.substr(semicolon + 1);
    if (parameter.size() < 2 || !equalsLower(parameter.substr(0, 2), "q="))
      continue;
    const std::string_view number = trimmed(parameter.substr(2));
    double q = 0.0;
    const auto [end, ec] = std::from_chars(number.data(), number.data() + number.size(), q);
    return ec == std::errc() && end == number.data() + number.size() && q >= 0.0 && q <= 1.0 ? q
                                                                                             : 0.0;
  }
  return 1.0;
}

} // namespace

bool acceptsGzip(std::string_view acceptEncoding) {
  double gzip = -1.0, any = -1.0; // -1: not listed
  while (!acceptEncoding.empty()) {
    const std::size_t comma = acceptEncoding.find(',');
    const std::string_view member = acceptEncoding.substr(0, comma);
    acceptEncoding =
        comma == std::string_view::npos ? std::string_view{} : acceptEncoding.substr(comma + 1);
    const std::size_t semicolon = member.find(';');
    const std::string_view coding = trimmed(member.substr(0, semicolon));
    const double q =
        semicolon == std::string_view::npos ? 1.0 : quality(member.substr(semicolon + 1));
    if (equalsLower(coding, "gzip") || equalsLower(coding, "x-gzip"))
      gzip = std::max(gzip, q);
    else if (coding == "*")
      any = std::max(any, q);
  }
  return gzip >= 0.0 ? gzip > 0.0 : any > 0.0;
}

std::string gzipped(std::string_view text) {
  z_stream stream{};
  // windowBits 15 + 16: a gzip header and trailer around the deflate stream.
  const int init = deflateInit2(&stream, Z_BEST_SPEED, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY);
  STRAHLER_ASSERT(init == Z_OK, "zlib could not start a gzip stream");
  STRAHLER_ASSERT(text.size() <= std::numeric_limits<uInt>::max(),
                  "text too large for one zlib call");
  std::string out(deflateBound(&stream, static_cast<uLong>(text.size())), '\0');
  stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(text.data()));
  stream.avail_in = static_cast<uInt>(text.size());
  stream.next_out = reinterpret_cast<Bytef*>(out.data());
  stream.avail_out = static_cast<uInt>(out.size());
  const int result = deflate(&stream, Z_FINISH);
  deflateEnd(&stream);
  STRAHLER_ASSERT(result == Z_STREAM_END, "zlib's bound did not hold the gzip stream");
  out.resize(stream.total_out);
  out.shrink_to_fit();
  return out;
}

} // namespace strahler::app
