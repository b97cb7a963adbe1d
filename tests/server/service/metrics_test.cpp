#include "metrics.h"

#include <gtest/gtest.h>

#include <atomic>
#include <limits>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace strahler::service {
namespace {

std::vector<std::string> linesOf(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream stream(text);
  for (std::string line; std::getline(stream, line);) {
    lines.push_back(line);
  }
  return lines;
}

/// The value of the sample line that starts with `series` (name plus labels), or -1.
double sampleValue(const std::string& text, const std::string& series) {
  for (const std::string& line : linesOf(text)) {
    if (line.rfind(series + " ", 0) == 0) {
      return std::stod(line.substr(series.size() + 1));
    }
  }
  return -1.0;
}

/// A metric sample line of the text format 0.0.4: name, optional escaped labels, value.
const std::regex
    kSampleLine(R"(^[a-zA-Z_:][a-zA-Z0-9_:]*(\{[a-zA-Z_][a-zA-Z0-9_]*="([^"\\\n]|\\[\\"n])*")"
                R"((,[a-zA-Z_][a-zA-Z0-9_]*="([^"\\\n]|\\[\\"n])*")*\})? )"
                R"(([-+]?[0-9]*\.?[0-9]+([eE][-+]?[0-9]+)?|\+Inf|-Inf|NaN)$)");
const std::regex kCommentLine(R"(^# (HELP|TYPE) ([a-zA-Z_:][a-zA-Z0-9_:]*) (.+)$)");

/// Records a few requests of two routes and one tile.
void recordSomeTraffic(Metrics& metrics) {
  metrics.recordRequest("tile", 200, 4.0);
  metrics.recordRequest("tile", 304, 0.2);
  metrics.recordRequest("tile", 503, 1.0);
  metrics.recordRequest("health", 200, 0.05);
  metrics.recordTile(12.0, 3.0);
}

TEST(Metrics, ExpositionTextIsWellFormed) {
  Metrics metrics;
  recordSomeTraffic(metrics);
  const std::string text = metrics.render("strahler_cache_bytes 1024\n");
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.back(), '\n');
  std::map<std::string, std::string> types;
  for (const std::string& line : linesOf(text)) {
    std::smatch match;
    if (std::regex_match(line, match, kCommentLine)) {
      if (match[1] == "TYPE") {
        EXPECT_TRUE(types.emplace(match[2], match[3]).second) << "second TYPE for " << match[2];
      }
      continue;
    }
    EXPECT_TRUE(std::regex_match(line, kSampleLine)) << "malformed line: " << line;
  }
  EXPECT_EQ(types["strahler_http_requests_total"], "counter");
  EXPECT_EQ(types["strahler_http_request_duration_seconds"], "histogram");
  EXPECT_EQ(types["strahler_tile_evaluate_seconds"], "histogram");
  EXPECT_EQ(types["strahler_tile_encode_seconds"], "histogram");
  EXPECT_EQ(sampleValue(text, R"(strahler_http_requests_total{route="tile",status="304"})"), 1);
  EXPECT_EQ(sampleValue(text, "strahler_cache_bytes"), 1024);
}

TEST(Metrics, TypeLineComesBeforeTheSamplesOfItsFamily) {
  Metrics metrics;
  recordSomeTraffic(metrics);
  const std::string text = metrics.render({});
  const auto type = text.find("# TYPE strahler_http_request_duration_seconds histogram");
  const auto sample = text.find("strahler_http_request_duration_seconds_bucket");
  ASSERT_NE(type, std::string::npos);
  ASSERT_NE(sample, std::string::npos);
  EXPECT_LT(type, sample);
}

TEST(Metrics, HistogramBucketsAreCumulativeAndCountEqualsObservations) {
  Metrics metrics;
  for (const double ms : {0.5, 3.0, 3.0, 2000.0, 5000.0}) {
    metrics.recordRequest("tile", 200, ms);
  }
  const std::string text = metrics.render({});
  const std::vector<std::pair<std::string, double>> expected = {
      {"0.001", 1}, {"0.0025", 1}, {"0.005", 3}, {"0.01", 3}, {"0.025", 3}, {"0.05", 3},
      {"0.1", 3},   {"0.25", 3},   {"0.5", 3},   {"1", 3},    {"2.5", 4},   {"+Inf", 5}};
  double previous = 0;
  for (const auto& [le, count] : expected) {
    const std::string series =
        R"(strahler_http_request_duration_seconds_bucket{route="tile",le=")" + le + "\"}";
    const double value = sampleValue(text, series);
    EXPECT_EQ(value, count) << series;
    EXPECT_GE(value, previous) << "buckets must be cumulative";
    previous = value;
  }
  EXPECT_EQ(sampleValue(text, R"(strahler_http_request_duration_seconds_count{route="tile"})"), 5);
  EXPECT_NEAR(sampleValue(text, R"(strahler_http_request_duration_seconds_sum{route="tile"})"),
              7.0065, 1e-9);
}

TEST(Metrics, TileTimesGoToTheirOwnHistograms) {
  Metrics metrics;
  metrics.recordTile(2.0, 30.0);
  metrics.recordTile(2.0, 30.0);
  const std::string text = metrics.render({});
  EXPECT_EQ(sampleValue(text, R"(strahler_tile_evaluate_seconds_bucket{le="0.001"})"), 0);
  EXPECT_EQ(sampleValue(text, R"(strahler_tile_evaluate_seconds_bucket{le="0.0025"})"), 2);
  EXPECT_EQ(sampleValue(text, R"(strahler_tile_encode_seconds_bucket{le="0.025"})"), 0);
  EXPECT_EQ(sampleValue(text, R"(strahler_tile_encode_seconds_bucket{le="0.05"})"), 2);
  EXPECT_EQ(sampleValue(text, "strahler_tile_evaluate_seconds_count"), 2);
  EXPECT_NEAR(sampleValue(text, "strahler_tile_encode_seconds_sum"), 0.06, 1e-12);
}

TEST(Metrics, NegativeOrNonFiniteDurationsCountAsZero) {
  Metrics metrics;
  metrics.recordRequest("tile", 200, -5.0);
  metrics.recordRequest("tile", 200, std::numeric_limits<double>::quiet_NaN());
  const std::string text = metrics.render({});
  EXPECT_EQ(sampleValue(
                text, R"(strahler_http_request_duration_seconds_bucket{route="tile",le="0.001"})"),
            2);
  EXPECT_EQ(sampleValue(text, R"(strahler_http_request_duration_seconds_sum{route="tile"})"), 0);
}

TEST(Metrics, CountsRequestsByRouteAndStatus) {
  Metrics metrics;
  recordSomeTraffic(metrics);
  EXPECT_EQ(metrics.requestCount("tile", 200), 1u);
  EXPECT_EQ(metrics.requestCount("tile", 503), 1u);
  EXPECT_EQ(metrics.requestCount("health", 200), 1u);
  EXPECT_EQ(metrics.requestCount("health", 404), 0u);
  EXPECT_EQ(metrics.requestCount("nope", 200), 0u);
}

TEST(Metrics, EscapesBackslashQuoteAndNewlineInLabelValues) {
  EXPECT_EQ(escapeLabelValue("plain/route"), "plain/route");
  EXPECT_EQ(escapeLabelValue("a\"b\\c\nd"), R"(a\"b\\c\nd)");
  Metrics metrics;
  metrics.recordRequest("we\"ird\\\nroute", 400, 1.0);
  const std::string text = metrics.render({});
  EXPECT_NE(text.find(R"(strahler_http_requests_total{route="we\"ird\\\nroute",status="400"} 1)"),
            std::string::npos)
      << text;
  for (const std::string& line : linesOf(text)) {
    EXPECT_TRUE(line.rfind('#', 0) == 0 || std::regex_match(line, kSampleLine)) << line;
  }
}

TEST(Metrics, GaugesAreAppendedAsGivenAndEndWithNewline) {
  Metrics metrics;
  const std::string text = metrics.render("# TYPE strahler_queue gauge\nstrahler_queue 3");
  EXPECT_NE(text.find("# TYPE strahler_queue gauge\nstrahler_queue 3\n"), std::string::npos);
  EXPECT_EQ(text.back(), '\n');
}

TEST(Metrics, ConcurrentRecordingLosesNothing) {
  constexpr int kThreads = 4;
  constexpr int kPerThread = 1000;
  Metrics metrics;
  {
    std::vector<std::jthread> threads;
    for (int t = 0; t < kThreads; ++t) {
      threads.emplace_back([&] {
        for (int i = 0; i < kPerThread; ++i) {
          metrics.recordRequest("tile", 200, 1.0);
          metrics.recordTile(1.0, 1.0);
        }
      });
    }
  }
  EXPECT_EQ(metrics.requestCount("tile", 200), static_cast<std::size_t>(kThreads * kPerThread));
  const std::string text = metrics.render({});
  EXPECT_EQ(sampleValue(text, "strahler_tile_encode_seconds_count"), kThreads * kPerThread);
}

TEST(Metrics, ConcurrentFirstRecordingsOfNewSeriesCreateEachOnceAndLoseNothing) {
  constexpr int kThreads = 4;
  constexpr int kRounds = 200;
  const std::vector<std::string> routes = {"tile", "health", "metrics", "worlds", "rivers"};
  const std::vector<int> statuses = {200, 304, 404, 500, 503};
  Metrics metrics;
  std::atomic<bool> recording{true};
  std::jthread scraper([&] {
    while (recording.load()) { // renders while series are being added
      const std::string text = metrics.render({});
      ASSERT_EQ(text.back(), '\n');
    }
  });
  {
    std::vector<std::jthread> threads;
    for (int t = 0; t < kThreads; ++t) {
      threads.emplace_back([&, t] {
        for (int round = 0; round < kRounds; ++round) {
          for (std::size_t i = 0; i < routes.size(); ++i) {
            // Every thread visits the pairs in a different order, so first sightings race.
            const std::string& route = routes[(i + static_cast<std::size_t>(t)) % routes.size()];
            for (int status : statuses)
              metrics.recordRequest(route, status, 2.0);
          }
        }
      });
    }
  }
  recording = false;
  scraper.join();
  const std::string text = metrics.render({});
  for (const std::string& route : routes) {
    for (int status : statuses) {
      EXPECT_EQ(metrics.requestCount(route, status), static_cast<std::size_t>(kThreads * kRounds))
          << route << " " << status;
      const std::string series = "strahler_http_requests_total{route=\"" + route + "\",status=\"" +
                                 std::to_string(status) + "\"}";
      EXPECT_EQ(sampleValue(text, series), kThreads * kRounds) << series;
      std::size_t lines = 0;
      for (const std::string& line : linesOf(text))
        lines += line.rfind(series + " ", 0) == 0 ? 1 : 0;
      EXPECT_EQ(lines, 1u) << series; // created once, however many threads saw it first
    }
    const std::string labels = "{route=\"" + route + "\"}";
    const double perRoute = kThreads * kRounds * static_cast<double>(statuses.size());
    EXPECT_EQ(sampleValue(text, "strahler_http_request_duration_seconds_count" + labels), perRoute);
    EXPECT_NEAR(sampleValue(text, "strahler_http_request_duration_seconds_sum" + labels),
                perRoute * 0.002, 1e-9);
    EXPECT_EQ(sampleValue(text, "strahler_http_request_duration_seconds_bucket{route=\"" + route +
                                    "\",le=\"0.001\"}"),
              0.0);
    EXPECT_EQ(sampleValue(text, "strahler_http_request_duration_seconds_bucket{route=\"" + route +
                                    "\",le=\"0.0025\"}"),
              perRoute);
  }
}

} // namespace
} // namespace strahler::service
