// params.json's "vegetation" (issue 28): the vegetation layer's response curves by species,
// read, checked, and in the canonical JSON only when set (worlds without it keep their keys).
#include "result_matchers.h"

#include "strahler/input/params.h"

#include <gtest/gtest.h>

#include <string>

namespace strahler::input {
namespace {

constexpr const char* kTree =
    R"({"vegetation": {"tree": {"sediment": [0.5, 1.5, 10, 10], "illumination": [0.4, 0.7, 1, 1],
                                "humidity": [0.2, 0.5, 0.9, 1]}}})";

TEST(VegetationParams, SetCurvesParseAndRoundTripThroughTheCanonicalJson) {
  STRAHLER_ASSIGN_OR_ASSERT(Params p, parseParams(kTree));
  ASSERT_EQ(p.vegetation.count("tree"), 1u);
  EXPECT_EQ(p.vegetation.at("tree").sediment, (std::array<double, 4>{0.5, 1.5, 10, 10}));
  EXPECT_EQ(p.vegetation.at("tree").humidity, (std::array<double, 4>{0.2, 0.5, 0.9, 1}));
  const std::string text = canonicalJson(p);
  EXPECT_NE(text.find(R"(,"vegetation":{"tree":{"humidity":[0.2,0.5,0.9,1],)"), std::string::npos)
      << text;
  STRAHLER_ASSIGN_OR_ASSERT(Params again, parseParams(text));
  EXPECT_EQ(again, p);
  EXPECT_EQ(canonicalJson(again), text);
}

TEST(VegetationParams, WithoutThemTheCanonicalJsonIsUnchanged) {
  const std::string text = canonicalJson(Params{});
  EXPECT_EQ(text.find("vegetation"), std::string::npos);
  EXPECT_EQ(text.substr(text.size() - 17), R"("constraints":[]})");
}

TEST(VegetationParams, BadCurvesAreRefusedNamingThem) {
  const std::pair<const char*, const char*> cases[] = {
      {R"({"vegetation": []})", "must be an object of species"},
      {R"({"vegetation": {"oak": {}}})", "unknown species 'oak'"},
      {R"({"vegetation": {"tree": {"sediment": [0, 1, 2, 3]}}})", "must set all three curves"},
      {R"({"vegetation": {"bush": {"sediment": [0, 1, 2]}}})", "bush.sediment must be an array"},
      {R"({"vegetation": {"bush": {"shade": [0, 1, 2, 3]}}})", "unknown curve 'shade'"},
      {R"({"vegetation": {"bush": {"sediment": [0, "1", 2, 3]}}})", "must hold numbers"},
      {R"({"vegetation": {"bush": {"sediment": [0, 2, 1, 3], "illumination": [0, 0, 1, 1],
          "humidity": [0, 0, 1, 1]}}})",
       "bush.sediment must be four non-decreasing numbers"},
      {R"({"vegetation": {"bush": {"sediment": [-1, 0, 1, 1], "illumination": [0, 0, 1, 1],
          "humidity": [0, 0, 1, 1]}}})",
       "in [0, 10000]"},
  };
  for (const auto& [json, message] : cases) {
    const auto r = parseParams(json);
    ASSERT_FALSE(r.ok()) << json;
    EXPECT_NE(r.error().message.find(message), std::string::npos)
        << json << ": " << r.error().message;
  }
}

} // namespace
} // namespace strahler::input
