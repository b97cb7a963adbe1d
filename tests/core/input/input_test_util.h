#pragma once
// Helpers shared by the input tests: error matchers, GeoJSON builders, temp files.

#include "result_matchers.h"

#include "strahler/base/result.h"

#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace strahler::input::test_support {

using strahler::test_support::failsWith; // tests/support/result_matchers.h

using Position = std::array<double, 2>;
using RingPositions = std::vector<Position>;

/// JSON text of a ring's positions, written as given (close it yourself).
inline std::string ringJson(const RingPositions& ring) {
  std::ostringstream out;
  out.precision(17);
  out << "[";
  for (std::size_t i = 0; i < ring.size(); ++i)
    out << (i ? "," : "") << "[" << ring[i][0] << "," << ring[i][1] << "]";
  out << "]";
  return out.str();
}

/// JSON text of a polygon's coordinates (outer ring, then holes).
inline std::string polygonCoordinates(const std::vector<RingPositions>& rings) {
  std::string out = "[";
  for (std::size_t i = 0; i < rings.size(); ++i)
    out += (i ? "," : "") + ringJson(rings[i]);
  return out + "]";
}

/// A GeoJSON Polygon geometry.
inline std::string polygonJson(const std::vector<RingPositions>& rings) {
  return R"({"type":"Polygon","coordinates":)" + polygonCoordinates(rings) + "}";
}

/// A Feature around a geometry's JSON text.
inline std::string featureJson(const std::string& geometry) {
  return R"({"type":"Feature","properties":{},"geometry":)" + geometry + "}";
}

/// A FeatureCollection of feature texts.
inline std::string collectionJson(const std::vector<std::string>& features) {
  std::string out = R"({"type":"FeatureCollection","features":[)";
  for (std::size_t i = 0; i < features.size(); ++i)
    out += (i ? "," : "") + features[i];
  return out + "]}";
}

/// A closed, counter-clockwise axis-aligned square ring.
inline RingPositions square(double west, double south, double side) {
  return {{west, south},
          {west + side, south},
          {west + side, south + side},
          {west, south + side},
          {west, south}};
}

/// A fresh folder under the build tree, named after the running test.
inline std::filesystem::path tempDir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::filesystem::path dir = std::filesystem::path(STRAHLER_BINARY_DIR) / "test_tmp" /
                                    "input_test" / info->test_suite_name() / info->name();
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

/// Writes `text` to `path` and returns the path as a string.
inline std::string writeFile(const std::filesystem::path& path, std::string_view text) {
  std::ofstream out(path, std::ios::binary);
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  return path.string();
}

/// The contents of a file of the test data folder.
inline std::string readTestData(const std::string& name) {
  std::ifstream in(std::filesystem::path(STRAHLER_TEST_DATA_DIR) / name, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

} // namespace strahler::input::test_support
