#include "metrics.h"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <map>
#include <mutex>
#include <utility>

namespace strahler::service {

namespace {

/// Upper bounds of the latency buckets, in seconds, and their `le` labels (+Inf implied).
constexpr std::array<double, 11> kBucketBounds = {0.001, 0.0025, 0.005, 0.01, 0.025, 0.05,
                                                  0.1,   0.25,   0.5,   1.0,  2.5};
constexpr std::array<const char*, 11> kBucketLabels = {
    "0.001", "0.0025", "0.005", "0.01", "0.025", "0.05", "0.1", "0.25", "0.5", "1", "2.5"};

/// Non-negative, finite seconds from milliseconds; anything else counts as zero.
double toSeconds(double milliseconds) {
  return std::isfinite(milliseconds) && milliseconds > 0.0 ? milliseconds / 1000.0 : 0.0;
}

std::string formatDouble(double value) {
  std::array<char, 32> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  return std::string(buffer.data(), result.ptr);
}

/// A Prometheus histogram: per-bucket counts (made cumulative when rendered), sum, count.
struct Histogram {
  std::array<std::uint64_t, kBucketBounds.size()> buckets{}; ///< Not cumulative.
  std::uint64_t count = 0;
  double sum = 0.0;

  void observe(double seconds) {
    for (std::size_t i = 0; i < kBucketBounds.size(); ++i) {
      if (seconds <= kBucketBounds[i]) {
        ++buckets[i];
        break;
      }
    }
    ++count;
    sum += seconds;
  }

  /// Appends the _bucket, _sum and _count lines; `labels` is empty or `name="value",...`.
  void render(std::string& out, const std::string& name, const std::string& labels) const {
    const std::string prefix = labels.empty() ? std::string() : labels + ",";
    std::uint64_t cumulative = 0;
    for (std::size_t i = 0; i < kBucketBounds.size(); ++i) {
      cumulative += buckets[i];
      out += name + "_bucket{" + prefix + "le=\"" + kBucketLabels[i] + "\"} " +
             std::to_string(cumulative) + "\n";
    }
    out += name + "_bucket{" + prefix + "le=\"+Inf\"} " + std::to_string(count) + "\n";
    const std::string braces = labels.empty() ? std::string() : "{" + labels + "}";
    out += name + "_sum" + braces + " " + formatDouble(sum) + "\n";
    out += name + "_count" + braces + " " + std::to_string(count) + "\n";
  }
};

void appendHeader(std::string& out, const char* name, const char* type, const char* help) {
  out += std::string("# HELP ") + name + " " + help + "\n";
  out += std::string("# TYPE ") + name + " " + type + "\n";
}

std::string routeLabel(const std::string& route) {
  return "route=\"" + escapeLabelValue(route) + "\"";
}

} // namespace

std::string escapeLabelValue(std::string_view value) {
  std::string escaped;
  escaped.reserve(value.size());
  for (const char c : value) {
    if (c == '\\') {
      escaped += "\\\\";
    } else if (c == '"') {
      escaped += "\\\"";
    } else if (c == '\n') {
      escaped += "\\n";
    } else {
      escaped += c;
    }
  }
  return escaped;
}

struct Metrics::Impl {
  mutable std::mutex mutex;
  std::map<std::pair<std::string, int>, std::uint64_t> requests; ///< (route, status) -> count.
  std::map<std::string, Histogram> durations;                    ///< Per route.
  Histogram evaluate;
  Histogram encode;

  void renderRequests(std::string& out) const {
    appendHeader(out, "strahler_http_requests_total", "counter",
                 "HTTP requests answered, by route and status code.");
    for (const auto& [labels, count] : requests) {
      out += "strahler_http_requests_total{" + routeLabel(labels.first) + ",status=\"" +
             std::to_string(labels.second) + "\"} " + std::to_string(count) + "\n";
    }
  }

  void renderDurations(std::string& out) const {
    appendHeader(out, "strahler_http_request_duration_seconds", "histogram",
                 "Time from request received to response written, by route.");
    for (const auto& [route, histogram] : durations) {
      histogram.render(out, "strahler_http_request_duration_seconds", routeLabel(route));
    }
  }

  void renderTileTimes(std::string& out) const {
    appendHeader(out, "strahler_tile_evaluate_seconds", "histogram",
                 "Time to evaluate the heights of one computed tile.");
    evaluate.render(out, "strahler_tile_evaluate_seconds", {});
    appendHeader(out, "strahler_tile_encode_seconds", "histogram",
                 "Time to encode one computed tile.");
    encode.render(out, "strahler_tile_encode_seconds", {});
  }
};

Metrics::Metrics() : impl_(std::make_unique<Impl>()) {}

Metrics::~Metrics() = default;

void Metrics::recordRequest(const std::string& route, int status, double milliseconds) {
  const double seconds = toSeconds(milliseconds);
  std::lock_guard lock(impl_->mutex);
  ++impl_->requests[{route, status}];
  impl_->durations[route].observe(seconds);
}

void Metrics::recordTile(double evaluateMs, double encodeMs) {
  const double evaluateSeconds = toSeconds(evaluateMs);
  const double encodeSeconds = toSeconds(encodeMs);
  std::lock_guard lock(impl_->mutex);
  impl_->evaluate.observe(evaluateSeconds);
  impl_->encode.observe(encodeSeconds);
}

std::string Metrics::render(const std::string& gauges) const {
  std::string out;
  {
    std::lock_guard lock(impl_->mutex);
    impl_->renderRequests(out);
    impl_->renderDurations(out);
    impl_->renderTileTimes(out);
  }
  out += gauges;
  if (!gauges.empty() && gauges.back() != '\n') {
    out += '\n'; // The format requires every line to end with a line feed.
  }
  return out;
}

std::size_t Metrics::requestCount(const std::string& route, int status) const {
  std::lock_guard lock(impl_->mutex);
  const auto found = impl_->requests.find({route, status});
  return found == impl_->requests.end() ? 0 : static_cast<std::size_t>(found->second);
}

} // namespace strahler::service
