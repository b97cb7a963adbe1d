#include "content_encoding.h"

#include <algorithm>
#include <cctype>
#include <charconv>

namespace strahler::app {
namespace {

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
    const std::string_view parameter = trimmedField(parameters.substr(0, semicolon));
    parameters =
        semicolon == std::string_view::npos ? std::string_view{} : parameters.substr(semicolon + 1);
    if (parameter.size() < 2 || !equalsLower(parameter.substr(0, 2), "q="))
      continue;
    const std::string_view number = trimmedField(parameter.substr(2));
    double q = 0.0;
    const auto [end, ec] = std::from_chars(number.data(), number.data() + number.size(), q);
    return ec == std::errc() && end == number.data() + number.size() && q >= 0.0 && q <= 1.0 ? q
                                                                                             : 0.0;
  }
  return 1.0;
}

} // namespace

std::string_view trimmedField(std::string_view s) noexcept {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t'))
    s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t'))
    s.remove_suffix(1);
  return s;
}

bool acceptsGzip(std::string_view acceptEncoding) {
  double gzip = -1.0, any = -1.0; // -1: not listed
  while (!acceptEncoding.empty()) {
    const std::size_t comma = acceptEncoding.find(',');
    const std::string_view member = acceptEncoding.substr(0, comma);
    acceptEncoding =
        comma == std::string_view::npos ? std::string_view{} : acceptEncoding.substr(comma + 1);
    const std::size_t semicolon = member.find(';');
    const std::string_view coding = trimmedField(member.substr(0, semicolon));
    const double q =
        semicolon == std::string_view::npos ? 1.0 : quality(member.substr(semicolon + 1));
    if (equalsLower(coding, "gzip") || equalsLower(coding, "x-gzip"))
      gzip = std::max(gzip, q);
    else if (coding == "*")
      any = std::max(any, q);
  }
  return gzip >= 0.0 ? gzip > 0.0 : any > 0.0;
}

} // namespace strahler::app
