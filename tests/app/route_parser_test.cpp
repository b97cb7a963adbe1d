#include "result_matchers.h"
#include "route_parser.h"

#include <gtest/gtest.h>

namespace strahler::app {
namespace {

TEST(RouteParser, SplitsAndDecodesPathAndQuery) {
  const auto t =
      parseTarget("/worlds/my%20island/tiles/3/4/2.png?size=512&encoding=terrarium&x=a%2Bb+c");
  STRAHLER_ASSERT_OK(t);
  EXPECT_EQ(t.value().segments,
            (std::vector<std::string>{"worlds", "my island", "tiles", "3", "4", "2.png"}));
  EXPECT_EQ(t.value().query.at("size"), "512");
  EXPECT_EQ(t.value().query.at("x"), "a+b c");
  EXPECT_TRUE(test_support::valueOf(parseTarget("/")).segments.empty());
  EXPECT_EQ(test_support::valueOf(parseTarget("/worlds/")).segments.size(), 1u);
}

TEST(RouteParser, RefusesAQueryParameterGivenTwice) {
  const auto t = parseTarget("/a?size=256&x=1&size=512");
  ASSERT_FALSE(t.ok());
  EXPECT_EQ(t.error().message, "query parameter 'size' is given twice");
  EXPECT_FALSE(parseTarget("/a?k&k").ok());
  EXPECT_TRUE(parseTarget("/a?k=1&&j=1&").ok());
}

TEST(RouteParser, RejectsMalformedTargets) {
  for (const char* bad : {"worlds", "/a/../b", "/a/./b", "/%2e%2e/x", "/a%zz", "/a%4", "/a%00b",
                          "/a//b", "/a%2Fb", "/a\x01", "/x?k=%ZZ"}) {
    const auto t = parseTarget(bad);
    ASSERT_FALSE(t.ok()) << bad;
    EXPECT_NE(t.error().message.find("malformed request target"), std::string::npos);
  }
}

TEST(RouteParser, ParsesBoundedDecimals) {
  EXPECT_EQ(test_support::valueOf(parseDecimal("0")), 0);
  EXPECT_EQ(test_support::valueOf(parseDecimal("1234567890")), 1234567890);
  EXPECT_EQ(parseDecimal("013880").error().message, "'013880' has a leading zero (write 13880)");
  for (const char* bad :
       {"", "-1", "+1", "1.5", "1e3", "12345678901", " 1", "0x10", "00", "01", "0007"}) {
    EXPECT_FALSE(parseDecimal(bad).ok()) << bad;
  }
}

TEST(RouteParser, ReadsATilesZxyAndNamesWhatIsWrong) {
  const std::vector<std::string> good{"12", "1736", "1494.mvt"};
  EXPECT_EQ(test_support::valueOf(parseZxy(good, ".mvt", "a vector tile")),
            (geometry::TileId{12, 1736, 1494}));
  const auto refused = [](std::vector<std::string> zxy, const char* suffix) {
    const auto t = parseZxy(zxy, suffix, "a vector tile");
    EXPECT_FALSE(t.ok());
    return t.ok() ? std::string() : t.error().message;
  };
  EXPECT_EQ(refused({"1", "0", "0.png"}, ".mvt"), "a vector tile is named {y}.mvt");
  EXPECT_EQ(refused({"1", "0", ".mvt"}, ".mvt"), "a vector tile is named {y}.mvt");
  EXPECT_EQ(refused({"100", "0", "0.mvt"}, ".mvt"),
            "tile coordinate '100' is not a non-negative integer of at most 2 digits");
  EXPECT_EQ(refused({"1", "x", "y.mvt"}, ".mvt"),
            "tile coordinate 'x' is not a non-negative integer");
  EXPECT_EQ(refused({"1", "0", "01.mvt"}, ".mvt"),
            "tile coordinate '01' has a leading zero (write 1)");
  EXPECT_EQ(test_support::valueOf(parseTileCoordinates("0", "0", "0")),
            (geometry::TileId{0, 0, 0}));
}

} // namespace
} // namespace strahler::app
