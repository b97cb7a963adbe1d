#include "ci_environment.h"
#include "result_matchers.h"

#include "strahler/image/image.h"
#include "strahler/quality/dem_file.h"
#include "strahler/quality/relief.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace strahler::quality {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  const fs::path dir =
      fs::path(STRAHLER_BINARY_DIR) / "dem_test_scratch" / std::to_string(::getpid());
  fs::create_directories(dir);
  return dir / name;
}

std::string writeText(const std::string& name, const std::string& text) {
  const fs::path path = scratch(name);
  std::ofstream(path, std::ios::binary) << text;
  return path.string();
}

constexpr const char* kHeader = "ncols 3\nnrows 2\nxllcorner 100\nyllcorner 200\ncellsize 10\n"
                                "NODATA_value -9999\n";

TEST(DemFile, ReadsAnEsriAsciiGridNorthRowFirst) {
  const std::string path = writeText("good.asc", std::string(kHeader) + "1 2 3\r\n4 -9999 6\n");
  STRAHLER_ASSIGN_OR_ASSERT(const auto raster, readEsriAsciiGrid(path));
  const HeightRaster& r = raster;
  EXPECT_EQ(r.width, 3);
  EXPECT_EQ(r.height, 2);
  EXPECT_DOUBLE_EQ(r.cellSize, 10.0);
  EXPECT_DOUBLE_EQ(r.origin.x, 105.0);
  EXPECT_DOUBLE_EQ(r.origin.y, 205.0);
  // Raster row 0 is the south row: the file's last line.
  EXPECT_EQ(r.heights[0], 4.0f);
  EXPECT_EQ(r.heights[2], 6.0f);
  EXPECT_EQ(r.heights[3], 1.0f);
  EXPECT_EQ(r.cellClass[1], std::uint8_t(CellClass::kSea)) << "NODATA is outside";
  EXPECT_EQ(r.cellClass[0], std::uint8_t(CellClass::kLand));
}

TEST(DemFile, AcceptsCentreCoordinatesAnyCaseAndValuesAcrossLines) {
  const std::string path = writeText(
      "centre.asc", "NCOLS 2\nNRows 2\nxllcenter 0\nyllcenter 0\nCellSize 5\n1 2\n3\n4\n");
  STRAHLER_ASSIGN_OR_ASSERT(const auto raster, readDemFile(path, std::nullopt));
  EXPECT_DOUBLE_EQ(raster.origin.x, 0.0);
  EXPECT_EQ(raster.heights[0], 3.0f);
  STRAHLER_ASSIGN_OR_ASSERT(const auto override, readDemFile(path, 30.0));
  EXPECT_DOUBLE_EQ(override.cellSize, 30.0);
}

struct BadGrid {
  const char* text;
  const char* message; ///< Part of the expected message.
};

class DemFileRejects : public ::testing::TestWithParam<BadGrid> {};

TEST_P(DemFileRejects, WithTheFileTheLineAndWhat) {
  const std::string path = writeText("bad.asc", GetParam().text);
  const auto raster = readEsriAsciiGrid(path);
  ASSERT_FALSE(raster.ok());
  EXPECT_NE(raster.error().message.find(path), std::string::npos) << raster.error().message;
  EXPECT_NE(raster.error().message.find(GetParam().message), std::string::npos)
      << raster.error().message;
}

INSTANTIATE_TEST_SUITE_P(
    Malformed, DemFileRejects,
    ::testing::Values(
        BadGrid{"ncols 2\nnrows 1\nxllcorner 0\nyllcorner 0\n1 2\n", "line 5: the header ends "
                                                                     "here without 'cellsize'"},
        BadGrid{"ncols 2\nnrows 1\nxllcorner 0\ncellsize 1\n1 2\n", "exactly one of 'yllcorner'"},
        BadGrid{"ncols 2\nnrows 1\nxllcorner 0\nxllcenter 0\nyllcorner 0\ncellsize 1\n1 2\n",
                "exactly one of 'xllcorner'"},
        BadGrid{"ncols 2\nnrows 1\nwidth 3\n", "line 3: unknown header key 'width'"},
        BadGrid{"ncols 2\nncols 2\n", "line 2: header key 'ncols' given twice"},
        BadGrid{"ncols two\n", "line 1: header value 'two' of 'ncols' is not a finite number"},
        BadGrid{"ncols 2.5\nnrows 1\nxllcorner 0\nyllcorner 0\ncellsize 1\n1 2\n",
                "line 1: 'ncols' must be a positive integer"},
        BadGrid{"ncols 2\nnrows 1\nxllcorner 0\nyllcorner 0\ncellsize -1\n1 2\n",
                "line 5: 'cellsize' must be positive"},
        BadGrid{"ncols 30000\nnrows 30000\nxllcorner 0\nyllcorner 0\ncellsize 1\n1 2\n",
                "line 2: 30000 x 30000 cells is more than the limit"},
        BadGrid{"ncols 2\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1\n1 2\n3 x4\n",
                "line 7: value 4 ('x4', row 2 column 2) is not a finite number"},
        BadGrid{"ncols 2\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1\n1 2\nnan 4\n",
                "line 7: value 3 ('nan', row 2 column 1) is not a finite number"},
        BadGrid{"ncols 2\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1\n1 2\n3\n",
                "line 7: the file ends after 3 values; ncols x nrows = 4"},
        BadGrid{"ncols 2\nnrows 1\nxllcorner 0\nyllcorner 0\ncellsize 1\n1 2\n3\n",
                "line 7: more values than ncols x nrows = 2"},
        BadGrid{"ncols 2\nnrows 1\n", "line 2: the file ends before the first value"}),
    [](const ::testing::TestParamInfo<BadGrid>& param) {
      return "case" + std::to_string(param.index);
    });

TEST(DemFile, AGridInDegreesIsResampledToSquareMetricCells) {
  // 6 x 2 cells of 0.001° centred on 60° N, where a degree of longitude is half one of
  // latitude: 3 columns of 111.3 m, sampling input columns 0, 2.5 and 5; the NODATA cell in
  // input column 3 is the nearest to output column 1 in the north row.
  const std::string path = writeText("degrees.asc", "ncols 6\nnrows 2\nxllcorner 10\n"
                                                    "yllcorner 59.999\ncellsize 0.001\n"
                                                    "NODATA_value -9999\n"
                                                    "0 10 20 -9999 40 50\n"
                                                    "100 110 120 130 140 150\n");
  const auto raster = readDemFile(path, std::nullopt);
  ASSERT_TRUE(raster.ok()) << raster.error().message;
  const HeightRaster& r = raster.value();
  EXPECT_EQ(r.width, 3);
  EXPECT_EQ(r.height, 2);
  EXPECT_NEAR(r.cellSize, 111.3195, 1e-3);
  // South row (the file's second) first.
  EXPECT_FLOAT_EQ(r.heights[0], 100.0f);
  EXPECT_FLOAT_EQ(r.heights[1], 125.0f);
  EXPECT_FLOAT_EQ(r.heights[2], 150.0f);
  EXPECT_EQ(r.cellClass[1], std::uint8_t(CellClass::kLand));
  EXPECT_EQ(r.cellClass[4], std::uint8_t(CellClass::kSea)) << "nearest to the NODATA cell";
  EXPECT_EQ(r.cellClass[5], std::uint8_t(CellClass::kLand));
  // A given cell size keeps the grid as it is.
  const auto given = readDemFile(path, 50.0);
  ASSERT_TRUE(given.ok());
  EXPECT_EQ(given.value().width, 6);
  EXPECT_EQ(given.value().cellSize, 50.0);
}

TEST(DemFile, AMissingFileIsNotFound) {
  const auto raster = readDemFile("/nonexistent/dem.asc", std::nullopt);
  ASSERT_FALSE(raster.ok());
  EXPECT_EQ(raster.error().code, base::ErrorCode::kNotFound);
  EXPECT_NE(raster.error().message.find("/nonexistent/dem.asc"), std::string::npos);
}

TEST(DemFile, ReadsImagesAsStoredValuesGivenACellSize) {
  image::RgbImage png{2, 2, {10, 0, 0, 20, 0, 0, 30, 0, 0, 250, 0, 0}};
  const std::string path = scratch("dem.png").string();
  STRAHLER_ASSERT_OK(image::writePng(path, png));
  const auto without = readDemFile(path, std::nullopt);
  ASSERT_FALSE(without.ok());
  EXPECT_NE(without.error().message.find("--cell-size"), std::string::npos);
  STRAHLER_ASSIGN_OR_ASSERT(const auto raster, readDemFile(path, 25.0));
  EXPECT_DOUBLE_EQ(raster.cellSize, 25.0);
  // Top image row first in the file, south row first in the raster; values not normalised.
  EXPECT_EQ(raster.heights[0], 30.0f);
  EXPECT_EQ(raster.heights[3], 20.0f);
  EXPECT_FALSE(readDemFile(writeText("junk.tif", "not an image"), 10.0).ok());
}

/// The published figures of ../shared/reference/orkhon-valley-92m.asc (see its README).
TEST(DemFile, TheOrkhonValleyReferenceGivesItsPublishedFigures) {
  const std::string path = std::string(STRAHLER_REFERENCE_DIR) + "/orkhon-valley-92m.asc";
  if (!fs::exists(path))
    STRAHLER_SKIP_UNLESS_CI(path << " is absent");
  STRAHLER_ASSIGN_OR_ASSERT(const auto raster, readDemFile(path, std::nullopt));
  EXPECT_EQ(raster.width, 98);
  EXPECT_EQ(raster.height, 180);
  const ReliefFigures f = measureRelief(raster);
  EXPECT_NEAR(f.slopeArea.theta, 0.34, 0.03);
  EXPECT_NEAR(f.slopeArea.r2, 0.98, 0.03);
  EXPECT_NEAR(f.slopes.p50Deg, 11.1, 0.5);
  EXPECT_NEAR(f.slopes.p90Deg, 17.0, 0.5);
  EXPECT_NEAR(f.slopes.p99Deg, 21.9, 0.5);
  EXPECT_EQ(f.slopes.steeperThan45, 0.0);
  EXPECT_EQ(f.confluences.threeOrMore, 0u);
  // The published 0.47 km/km² counts every channel cell as one cell side long (760 cells of
  // 91.67 m over 148.2 km²); ours counts diagonal steps √2 cells long, hence about 15 % more.
  const FlowField flow = computeFlowField(raster);
  std::size_t channelCells = 0;
  for (std::uint32_t c : flow.order)
    channelCells += flow.areaKm2[c] >= 1.0 ? 1 : 0;
  const double landKm2 = double(flow.order.size()) * std::pow(raster.cellSize, 2) * 1e-6;
  EXPECT_NEAR(double(channelCells) * raster.cellSize * 1e-3 / landKm2, 0.47, 0.01);
  EXPECT_NEAR(f.drainageDensity1, 0.54, 0.02);
  EXPECT_NEAR(f.dissection, 5.8, 0.4);
}

} // namespace
} // namespace strahler::quality
