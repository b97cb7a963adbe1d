#include "metrics.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

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

/// A Prometheus histogram recorded with relaxed atomics: per-bucket counts (made cumulative
/// when rendered, the last one being +Inf, so the count is their total) and the sum.
struct Histogram {
  std::array<std::atomic<std::uint64_t>, kBucketBounds.size() + 1> buckets{}; ///< Not cumulative.
  std::atomic<double> sum{0.0};

  void observe(double seconds) noexcept {
    std::size_t i = 0;
    while (i < kBucketBounds.size() && seconds > kBucketBounds[i])
      ++i;
    buckets[i].fetch_add(1, std::memory_order_relaxed);
    sum.fetch_add(seconds, std::memory_order_relaxed);
  }

  /// Appends the _bucket, _sum and _count lines; `labels` is empty or `name="value",...`.
  void render(std::string& out, const std::string& name, const std::string& labels) const {
    const std::string prefix = labels.empty() ? std::string() : labels + ",";
    std::uint64_t cumulative = 0;
    for (std::size_t i = 0; i < kBucketBounds.size(); ++i) {
      cumulative += buckets[i].load(std::memory_order_relaxed);
      out += name + "_bucket{" + prefix + "le=\"" + kBucketLabels[i] + "\"} " +
             std::to_string(cumulative) + "\n";
    }
    cumulative += buckets.back().load(std::memory_order_relaxed);
    out += name + "_bucket{" + prefix + "le=\"+Inf\"} " + std::to_string(cumulative) + "\n";
    const std::string braces = labels.empty() ? std::string() : "{" + labels + "}";
    out += name + "_sum" + braces + " " + formatDouble(sum.load(std::memory_order_relaxed)) + "\n";
    out += name + "_count" + braces + " " + std::to_string(cumulative) + "\n";
  }
};

/// The requests of one status code within a route. Nodes are only ever prepended to a list
/// and freed with the Metrics, so readers walk the lists without a lock.
struct StatusCount {
  StatusCount(int code, StatusCount* after) : status(code), next(after) {}
  const int status;
  std::atomic<std::uint64_t> count{0};
  StatusCount* const next;
};

/// Everything recorded for one route label.
struct RouteSeries {
  RouteSeries(std::string label, RouteSeries* after) : route(std::move(label)), next(after) {}
  const std::string route;
  Histogram durations;
  std::atomic<StatusCount*> statuses{nullptr};
  RouteSeries* const next;
};

/// The node of `list` for which `matches` holds, or null.
template <class Node, class Matches> Node* findIn(const std::atomic<Node*>& list, Matches matches) {
  for (Node* node = list.load(std::memory_order_acquire); node != nullptr; node = node->next)
    if (matches(*node))
      return node;
  return nullptr;
}

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
  std::mutex growth; ///< Serialises adding routes and statuses; recording takes no lock.
  std::atomic<RouteSeries*> routes{nullptr};
  std::vector<std::unique_ptr<RouteSeries>> ownedRoutes;   ///< Guarded by `growth`.
  std::vector<std::unique_ptr<StatusCount>> ownedStatuses; ///< Guarded by `growth`.
  Histogram evaluate;
  Histogram encode;

  RouteSeries* findRoute(const std::string& route) const {
    return findIn(routes, [&](const RouteSeries& r) { return r.route == route; });
  }

  /// The counter of (`route`, `status`), created the first time it is seen.
  std::pair<RouteSeries*, StatusCount*> series(const std::string& route, int status) {
    RouteSeries* r = findRoute(route);
    StatusCount* s =
        r ? findIn(r->statuses, [&](const StatusCount& c) { return c.status == status; }) : nullptr;
    if (s != nullptr)
      return {r, s};
    std::lock_guard lock(growth);
    if (r == nullptr && (r = findRoute(route)) == nullptr) {
      ownedRoutes.push_back(
          std::make_unique<RouteSeries>(route, routes.load(std::memory_order_relaxed)));
      r = ownedRoutes.back().get();
      routes.store(r, std::memory_order_release);
    }
    s = findIn(r->statuses, [&](const StatusCount& c) { return c.status == status; });
    if (s == nullptr) {
      ownedStatuses.push_back(
          std::make_unique<StatusCount>(status, r->statuses.load(std::memory_order_relaxed)));
      s = ownedStatuses.back().get();
      r->statuses.store(s, std::memory_order_release);
    }
    return {r, s};
  }

  /// The routes sorted by label, and each one's statuses sorted by code.
  std::vector<std::pair<const RouteSeries*, std::vector<const StatusCount*>>> sorted() const {
    std::vector<std::pair<const RouteSeries*, std::vector<const StatusCount*>>> out;
    for (const RouteSeries* r = routes.load(std::memory_order_acquire); r; r = r->next) {
      std::vector<const StatusCount*> statuses;
      for (const StatusCount* s = r->statuses.load(std::memory_order_acquire); s; s = s->next)
        statuses.push_back(s);
      std::sort(statuses.begin(), statuses.end(),
                [](const StatusCount* a, const StatusCount* b) { return a->status < b->status; });
      out.emplace_back(r, std::move(statuses));
    }
    std::sort(out.begin(), out.end(),
              [](const auto& a, const auto& b) { return a.first->route < b.first->route; });
    return out;
  }

  void renderRequests(std::string& out) const {
    appendHeader(out, "strahler_http_requests_total", "counter",
                 "HTTP requests answered, by route and status code.");
    for (const auto& [route, statuses] : sorted()) {
      for (const StatusCount* s : statuses) {
        out += "strahler_http_requests_total{" + routeLabel(route->route) + ",status=\"" +
               std::to_string(s->status) + "\"} " +
               std::to_string(s->count.load(std::memory_order_relaxed)) + "\n";
      }
    }
  }

  void renderDurations(std::string& out) const {
    appendHeader(out, "strahler_http_request_duration_seconds", "histogram",
                 "Time from request received to response written, by route.");
    for (const auto& [route, statuses] : sorted()) {
      route->durations.render(out, "strahler_http_request_duration_seconds",
                              routeLabel(route->route));
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
  const auto [series, count] = impl_->series(route, status);
  count->count.fetch_add(1, std::memory_order_relaxed);
  series->durations.observe(toSeconds(milliseconds));
}

void Metrics::recordTile(double evaluateMs, double encodeMs) {
  impl_->evaluate.observe(toSeconds(evaluateMs));
  impl_->encode.observe(toSeconds(encodeMs));
}

std::string Metrics::render(const std::string& gauges) const {
  std::string out;
  impl_->renderRequests(out);
  impl_->renderDurations(out);
  impl_->renderTileTimes(out);
  out += gauges;
  if (!gauges.empty() && gauges.back() != '\n') {
    out += '\n'; // The format requires every line to end with a line feed.
  }
  return out;
}

std::size_t Metrics::requestCount(const std::string& route, int status) const {
  const RouteSeries* series = impl_->findRoute(route);
  const StatusCount* count =
      series ? findIn(series->statuses, [&](const StatusCount& c) { return c.status == status; })
             : nullptr;
  return count ? static_cast<std::size_t>(count->count.load(std::memory_order_relaxed)) : 0;
}

} // namespace strahler::service
