#include "input_test_util.h"

#include "strahler/input/params.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <string>

namespace strahler::input {
namespace {

using base::ErrorCode;
using test_support::failsWith;

TEST(Params, EmptyObjectGivesTheDefaults) {
  EXPECT_TRUE(validateParams(Params{}).ok());
  STRAHLER_ASSIGN_OR_ASSERT(auto parsed, parseParams("{}"));
  EXPECT_EQ(parsed, Params{});
}

TEST(Params, ReadsEveryKindOfField) {
  auto parsed = parseParams(R"({"edgeLength": 500, "sigma": 400.5, "fillBranches": 1,
      "seed": 42, "constraints": [{"kind": "riverSlope", "image": "slope.png",
      "bounds": [2.5, 39, 3.5, 40]}]})");
  ASSERT_TRUE(parsed.ok()) << parsed.error().message;
  const Params& p = parsed.value();
  EXPECT_EQ(p.edgeLength, 500.0);
  EXPECT_EQ(p.sigma, 400.5);
  EXPECT_EQ(p.fillBranches, 1);
  EXPECT_EQ(p.seed, 42u);
  ASSERT_EQ(p.constraints.size(), 1u);
  EXPECT_EQ(p.constraints[0].kind, ConstraintKind::kRiverSlope);
  EXPECT_EQ(p.constraints[0].imagePath, "slope.png");
  EXPECT_EQ(p.constraints[0].bounds, (GeoBounds{2.5, 39, 3.5, 40}));
}

TEST(Params, UnknownKeySuggestsTheClosestKey) {
  EXPECT_TRUE(failsWith(parseParams(R"({"sigmaa": 900})"), ErrorCode::kInvalidInput,
                        "params: unknown key 'sigmaa' (did you mean 'sigma'?)"));
  EXPECT_TRUE(failsWith(parseParams(R"({"edge_length": 900})"), ErrorCode::kInvalidInput,
                        "(did you mean 'edgeLength'?)"));
  auto far = parseParams(R"({"foo": 1})");
  EXPECT_TRUE(failsWith(far, ErrorCode::kInvalidInput, "params: unknown key 'foo'"));
  EXPECT_EQ(far.error().message.find("did you mean"), std::string::npos);
  // Keys are echoed escaped and cut short, however long or strange they are.
  auto odd = parseParams("{\"" + std::string(5000, 'x') + "\\u0001\": 1}");
  EXPECT_TRUE(failsWith(odd, ErrorCode::kInvalidInput, "params: unknown key 'xxxx"));
  EXPECT_LT(odd.error().message.size(), 120u);
  EXPECT_TRUE(failsWith(parseParams("{\"a\\u0001\": 1}"), ErrorCode::kInvalidInput,
                        "unknown key 'a\\u0001'"));
}

TEST(Params, WrongType) {
  EXPECT_TRUE(failsWith(parseParams(R"({"sigma": "big"})"), ErrorCode::kInvalidInput,
                        "params: 'sigma' must be a number, got a string"));
  EXPECT_TRUE(failsWith(parseParams(R"({"constraints": {}})"), ErrorCode::kInvalidInput,
                        "'constraints' must be an array"));
}

TEST(Params, NotAnObject) {
  EXPECT_TRUE(failsWith(parseParams("[1, 2]"), ErrorCode::kInvalidInput,
                        "params: expected a JSON object, got an array"));
  EXPECT_TRUE(failsWith(parseParams("{\"sigma\": 900,}"), ErrorCode::kInvalidInput,
                        "params: not valid JSON at byte"));
}

TEST(Params, DuplicateKey) {
  EXPECT_TRUE(failsWith(parseParams(R"({"sigma": 900, "sigma": 1000})"), ErrorCode::kInvalidInput,
                        "duplicate key \"sigma\""));
}

TEST(Params, ProbabilitiesMustSumToOne) {
  EXPECT_TRUE(failsWith(parseParams(R"({"probContinue": 0.5})"), ErrorCode::kInvalidInput,
                        "probContinue + probAsymmetric + probSymmetric = 1.3"));
  EXPECT_TRUE(
      parseParams(R"({"probContinue": 0.3, "probAsymmetric": 0.6, "probSymmetric": 0.1})").ok());
}

TEST(Params, SigmaMustExceedEdgeLengthOverRootTwo) {
  auto parsed = parseParams(R"({"edgeLength": 1000, "sigma": 700})");
  EXPECT_TRUE(failsWith(parsed, ErrorCode::kInvalidInput, "σ = 700"));
  EXPECT_TRUE(failsWith(parsed, ErrorCode::kInvalidInput, "e/√2 = 707.107"));
  EXPECT_TRUE(failsWith(parsed, ErrorCode::kInvalidInput, "edgeLength e = 1000"));
  EXPECT_TRUE(parseParams(R"({"edgeLength": 1000, "sigma": 708})").ok());
}

TEST(Params, NegativeEdgeLength) {
  EXPECT_TRUE(failsWith(parseParams(R"({"edgeLength": -5})"), ErrorCode::kOutOfRange,
                        "params: 'edgeLength' = -5 m is outside [50, 20000] m"));
}

TEST(Params, EveryRangeIsEnforced) {
  const struct {
    const char* json;
    ErrorCode code;
    const char* part;
  } cases[] = {
      {R"({"kappa": 0})", ErrorCode::kOutOfRange, "'kappa' = 0 is outside (0, 10]"},
      {R"({"delta": -1})", ErrorCode::kOutOfRange, "'delta' = -1 m must be >= 0 m"},
      {R"({"delta": 10000})", ErrorCode::kInvalidInput, "'delta' = 10000 m must be less than"},
      {R"({"zeta": -1})", ErrorCode::kOutOfRange, "'zeta'"},
      {R"({"probSymmetric": 1.5})", ErrorCode::kOutOfRange, "'probSymmetric' = 1.5"},
      {R"({"branchAngle": 0})", ErrorCode::kOutOfRange, "'branchAngle' = 0 degrees"},
      {R"({"angleJitter": 61})", ErrorCode::kOutOfRange, "'angleJitter'"},
      {R"({"fillBranches": 3})", ErrorCode::kOutOfRange, "'fillBranches' = 3 is outside [1, 2]"},
      {R"({"fillBranches": 0})", ErrorCode::kOutOfRange, "'fillBranches' = 0 is outside [1, 2]"},
      {R"({"tributaryLevels": 4})", ErrorCode::kOutOfRange,
       "'tributaryLevels' = 4 is outside [0, 3]"},
      {R"({"tributaryLevels": -1})", ErrorCode::kOutOfRange, "'tributaryLevels' = -1"},
      {R"({"erosionCell": 20})", ErrorCode::kOutOfRange,
       "'erosionCell' = 20 m is outside [30, 120] m"},
      {R"({"erosionSteps": 201})", ErrorCode::kOutOfRange, "'erosionSteps' = 201"},
      {R"({"erosionSteps": 2.5})", ErrorCode::kInvalidInput, "'erosionSteps'"},
      {R"({"erosionStrength": -1})", ErrorCode::kOutOfRange, "'erosionStrength' = -1"},
      {R"({"hillslopeDiffusivity": 6})", ErrorCode::kOutOfRange, "'hillslopeDiffusivity' = 6"},
      {R"({"erosionGrain": 9})", ErrorCode::kOutOfRange, "'erosionGrain' = 9"},
      {R"({"slopeMin": 0.1, "slopeMax": 0.05})", ErrorCode::kInvalidInput,
       "'slopeMin' = 0.1 must not exceed 'slopeMax' = 0.05"},
      {R"({"slopeMax": 0.7})", ErrorCode::kInvalidInput, "'slopeMax' = 0.7 must be less than"},
      {R"({"slopeJitter": 1})", ErrorCode::kOutOfRange, "'slopeJitter' = 1 is outside [0, 1)"},
      {R"({"coastRamp": 0})", ErrorCode::kOutOfRange, "'coastRamp' = 0 m must be > 0 m"},
      {R"({"maxPriority": 13})", ErrorCode::kOutOfRange, "'maxPriority' = 13"},
      {R"({"mouthSpacing": -3})", ErrorCode::kOutOfRange, "'mouthSpacing'"},
      {R"({"accessibilityRadius": 0})", ErrorCode::kOutOfRange, "'accessibilityRadius'"},
      {R"({"lambda": 1.5})", ErrorCode::kOutOfRange, "'lambda' = 1.5 is outside [0, 1]"},
      {R"({"lambdaCoastFactor": 0})", ErrorCode::kOutOfRange, "'lambdaCoastFactor'"},
      {R"({"straightMinSlope": -0.1})", ErrorCode::kOutOfRange, "'straightMinSlope'"},
      {R"({"braidedMinFlow": -1})", ErrorCode::kOutOfRange, "'braidedMinFlow' = -1 m³/s"},
      {R"({"braidedMaxDistance": -1})", ErrorCode::kOutOfRange, "'braidedMaxDistance'"},
      {R"({"deltaMinFlow": -1})", ErrorCode::kOutOfRange, "'deltaMinFlow'"},
  };
  for (const auto& c : cases)
    EXPECT_TRUE(failsWith(parseParams(c.json), c.code, c.part)) << c.json;
}

TEST(Params, ValidateRejectsNonFiniteValues) {
  Params p;
  p.zeta = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(
      failsWith(validateParams(p), ErrorCode::kOutOfRange, "'zeta' is not a finite number"));
  p = Params{};
  p.sigma = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(validateParams(p).ok());
}

TEST(Params, SeedAsString) {
  STRAHLER_ASSIGN_OR_ASSERT(auto big, parseParams(R"({"seed": "18446744073709551615"})"));
  EXPECT_EQ(big.seed, std::numeric_limits<std::uint64_t>::max());
  EXPECT_EQ(strahler::test_support::valueOf(parseParams(R"({"seed": "007"})")).seed, 7u);
  EXPECT_TRUE(failsWith(parseParams(R"({"seed": "18446744073709551616"})"), ErrorCode::kOutOfRange,
                        "larger than 2^64-1"));
  EXPECT_TRUE(failsWith(parseParams(R"({"seed": "12a"})"), ErrorCode::kInvalidInput,
                        "'seed' string must hold only decimal digits"));
  EXPECT_TRUE(
      failsWith(parseParams(R"({"seed": ""})"), ErrorCode::kInvalidInput, "decimal digits"));
}

TEST(Params, SeedAsNumber) {
  EXPECT_EQ(strahler::test_support::valueOf(parseParams(R"({"seed": 18446744073709551615})")).seed,
            std::numeric_limits<std::uint64_t>::max());
  EXPECT_EQ(strahler::test_support::valueOf(parseParams(R"({"seed": 1e3})")).seed, 1000u);
  EXPECT_TRUE(failsWith(parseParams(R"({"seed": -1})"), ErrorCode::kOutOfRange,
                        "'seed' must be a non-negative integer, got -1"));
  EXPECT_TRUE(failsWith(parseParams(R"({"seed": 1e19})"), ErrorCode::kInvalidInput,
                        "write it as a decimal string"));
  EXPECT_TRUE(failsWith(parseParams(R"({"seed": 1.5})"), ErrorCode::kInvalidInput,
                        "non-negative integer, got 1.5"));
  EXPECT_TRUE(failsWith(parseParams(R"({"seed": true})"), ErrorCode::kInvalidInput,
                        "'seed' must be a non-negative integer or a decimal string"));
}

TEST(Params, FillBranchesMustBeAnInteger) {
  EXPECT_TRUE(failsWith(parseParams(R"({"fillBranches": 2.5})"), ErrorCode::kInvalidInput,
                        "params: 'fillBranches' must be an integer, got 2.5"));
  EXPECT_EQ(strahler::test_support::valueOf(parseParams(R"({"fillBranches": 1.0})")).fillBranches,
            1);
  EXPECT_TRUE(
      failsWith(parseParams(R"({"maxPriority": 1e12})"), ErrorCode::kOutOfRange, "'maxPriority'"));
}

std::string constraintJson(const std::string& kind, const std::string& bounds) {
  return R"({"constraints": [{"kind": ")" + kind + R"(", "image": "m.png", "bounds": )" + bounds +
         "}]}";
}

TEST(Params, BadConstraintKind) {
  EXPECT_TRUE(failsWith(parseParams(constraintJson("height", "[0, 0, 1, 1]")),
                        ErrorCode::kInvalidInput,
                        "params: constraints[0]: 'kind' is \"height\"; expected "
                        "\"mountainousness\" or \"riverSlope\""));
}

TEST(Params, ConstraintBoundsInverted) {
  EXPECT_TRUE(failsWith(parseParams(constraintJson("mountainousness", "[1, 0, 0, 1]")),
                        ErrorCode::kInvalidInput,
                        "constraints[0]: bounds [1, 0, 0, 1] must be [west, south, east, north] "
                        "with west < east and south < north"));
  EXPECT_TRUE(failsWith(parseParams(constraintJson("mountainousness", "[0, 1, 1, 0]")),
                        ErrorCode::kInvalidInput, "south < north"));
  EXPECT_TRUE(failsWith(parseParams(constraintJson("mountainousness", "[0, -91, 1, 0]")),
                        ErrorCode::kOutOfRange, "latitude outside [-90, 90]"));
  EXPECT_TRUE(failsWith(parseParams(constraintJson("mountainousness", "[0, 0, 1]")),
                        ErrorCode::kInvalidInput, "'bounds' must be an array of 4 numbers"));
}

TEST(Params, ConstraintObjectsAreChecked) {
  EXPECT_TRUE(
      failsWith(parseParams(R"({"constraints": [{"kind": "riverSlope", "bounds": [0, 0, 1, 1]}]})"),
                ErrorCode::kInvalidInput, "constraints[0]: missing 'image'"));
  EXPECT_TRUE(failsWith(parseParams(R"({"constraints": [{"kind": "riverSlope", "imag": "a",
      "image": "b", "bounds": [0, 0, 1, 1]}]})"),
                        ErrorCode::kInvalidInput,
                        "constraints[0]: unknown key 'imag' (did you mean 'image'?)"));
  EXPECT_TRUE(failsWith(parseParams(R"({"constraints": [{"kind": "riverSlope", "image": "",
      "bounds": [0, 0, 1, 1]}]})"),
                        ErrorCode::kInvalidInput, "'image' is an empty path"));
}

TEST(Params, AtMostSixteenConstraints) {
  std::string json = R"({"constraints": [)";
  for (int i = 0; i < 17; ++i)
    json += std::string(i ? "," : "") +
            R"({"kind": "riverSlope", "image": "a.png", "bounds": [0, 0, 1, 1]})";
  EXPECT_TRUE(failsWith(parseParams(json + "]}"), ErrorCode::kLimitExceeded,
                        "'constraints' has 17 entries, the limit is 16"));
}

TEST(Params, CanonicalJsonRoundTripsExactly) {
  Params p;
  p.edgeLength = 1234.5678901234567;
  p.sigma = 0.1 + 0.2 + 1000.0;
  p.delta = 1.0 / 3.0;
  p.kappa = 0.1 + 0.2; // 0.30000000000000004: needs all 17 digits
  p.probContinue = 0.1;
  p.probAsymmetric = 0.2;
  p.probSymmetric = 0.7;
  p.fillBranches = 1;
  p.maxPriority = 12;
  p.braidedMaxDistance = 1e21;
  p.seed = std::numeric_limits<std::uint64_t>::max();
  p.constraints.push_back({ConstraintKind::kRiverSlope, "dir/\"quoted\" \\ é.png",
                           GeoBounds{-0.1, -45.25, 179.999999999, 89.5}});
  p.constraints.push_back({ConstraintKind::kMountainousness, "m.tif", GeoBounds{1, 2, 3, 4}});
  ASSERT_TRUE(validateParams(p).ok()) << validateParams(p).error().message;
  const std::string text = canonicalJson(p);
  STRAHLER_ASSIGN_OR_ASSERT(auto parsed, parseParams(text));
  EXPECT_EQ(parsed, p) << text;
  EXPECT_EQ(canonicalJson(parsed), text);
}

TEST(Params, CanonicalJsonHasAFixedKeyOrder) {
  const std::string text = canonicalJson(Params{});
  EXPECT_EQ(text.rfind(R"({"edgeLength":1000,"sigma":)", 0), 0u) << text;
  EXPECT_NE(text.find(R"("deltaMinFlow":6,"seed":1,"constraints":[]})"), std::string::npos) << text;
  EXPECT_EQ(text.find(' '), std::string::npos);
  EXPECT_EQ(strahler::test_support::valueOf(parseParams(text)), Params{});
}

TEST(Params, ErosionKeysAreInTheCanonicalJsonOnlyWithErosion) {
  // Worlds without erosion keep their canonical text (and cache keys).
  Params p;
  p.erosionStrength = 2.0; // ignored while erosionSteps is 0
  EXPECT_EQ(canonicalJson(p).find("erosion"), std::string::npos);
  EXPECT_EQ(canonicalJson(p).find("hillslopeDiffusivity"), std::string::npos);
  p.erosionSteps = 20;
  const std::string text = canonicalJson(p);
  EXPECT_NE(text.find(R"("erosionCell":60,"erosionSteps":20,"erosionStrength":2,)"
                      R"("hillslopeDiffusivity":1,"erosionGrain":1,"seed":1)"),
            std::string::npos)
      << text;
  auto parsed = parseParams(text);
  ASSERT_TRUE(parsed.ok()) << parsed.error().message;
  EXPECT_EQ(parsed.value(), p);
}

TEST(Params, TributaryLevelsAreInTheCanonicalJsonOnlyWhenSet) {
  // Worlds made before the option existed keep their canonical text (and cache keys).
  EXPECT_EQ(canonicalJson(Params{}).find("tributaryLevels"), std::string::npos);
  Params p;
  p.tributaryLevels = 2;
  const std::string text = canonicalJson(p);
  EXPECT_NE(text.find(R"("deltaMinFlow":6,"tributaryLevels":2,"seed":1)"), std::string::npos)
      << text;
  auto parsed = parseParams(text);
  ASSERT_TRUE(parsed.ok()) << parsed.error().message;
  EXPECT_EQ(parsed.value().tributaryLevels, 2);
  EXPECT_EQ(parseParams(R"({"tributaryLevels": 3})").value().tributaryLevels, 3);
}

TEST(Params, TheGrowerIsInTheCanonicalJsonOnlyWhenNotTheGrammar) {
  // Worlds made before issue 30 keep their canonical text (and cache keys).
  EXPECT_EQ(canonicalJson(Params{}).find("grower"), std::string::npos);
  EXPECT_EQ(parseParams(R"({"grower": "grammar"})").value(), Params{});
  Params p;
  p.grower = NetworkGrower::kDla;
  const std::string text = canonicalJson(p);
  EXPECT_NE(text.find(R"("constraints":[],"grower":"dla"})"), std::string::npos) << text;
  auto parsed = parseParams(text);
  ASSERT_TRUE(parsed.ok()) << parsed.error().message;
  EXPECT_EQ(parsed.value(), p);
}

TEST(Params, AnUnknownGrowerIsRefusedByName) {
  EXPECT_TRUE(failsWith(parseParams(R"({"grower": "lsystem"})"), ErrorCode::kInvalidInput,
                        "params: 'grower': unknown grower 'lsystem': expected \"grammar\""));
  EXPECT_TRUE(failsWith(parseParams(R"({"grower": 2})"), ErrorCode::kInvalidInput,
                        "params: 'grower' must be a string"));
  EXPECT_EQ(parseGrower("dla").value(), NetworkGrower::kDla);
  EXPECT_STREQ(growerName(NetworkGrower::kDla), "dla");
  EXPECT_STREQ(growerName(NetworkGrower::kGrammar), "grammar");
}

} // namespace
} // namespace strahler::input
