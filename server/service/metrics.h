#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>

namespace strahler::service {

/// `value` escaped for a Prometheus label value: backslash, double quote and line feed become
/// \\, \" and \n. For callers that format their own gauge lines.
std::string escapeLabelValue(std::string_view value);

/// Counters and histograms exposed at /metrics in the Prometheus text format (0.0.4).
/// Thread-safe; recording takes no lock (relaxed atomic counters; a lock only the first time a
/// route and status pair is seen), so I/O threads never wait for each other or for a scrape.
class Metrics {
public:
  Metrics();
  ~Metrics();

  /// One finished HTTP request: route label, status code, duration (negative or non-finite
  /// durations count as zero).
  void recordRequest(const std::string& route, int status, double milliseconds);
  /// One computed tile: evaluation and encoding times (milliseconds).
  void recordTile(double evaluateMs, double encodeMs);
  /// The exposition text. `gauges` lines (already formatted, e.g. cache bytes, queue depth)
  /// are appended as given.
  std::string render(const std::string& gauges) const;

  /// Requests seen so far with this route and status (for tests).
  std::size_t requestCount(const std::string& route, int status) const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace strahler::service
