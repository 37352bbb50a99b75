// The compact stand-ins of the shared structs (OptionalSeconds, OptionalPeriodic, TargetName)
// behave as the std::optional and std::string they replace.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <sstream>

#include "fapc/timeline/schedule.hpp"
#include "fapc/timeline/timeline.hpp"

namespace fapc {
namespace {

TEST(OptionalSeconds, HoldsEveryDoubleNaNIncludedAndConvertsBothWays) {
  OptionalSeconds none;
  EXPECT_FALSE(none.has_value());
  EXPECT_EQ(none.value_or(4), 4);
  EXPECT_THROW((void)none.value(), std::bad_optional_access);
  for (const double v :
       {0.0, -0.0, 1e-320, -3.5, std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN()}) {
    const OptionalSeconds some = v;
    ASSERT_TRUE(some.has_value()) << v;
    EXPECT_EQ(std::signbit(*some), std::signbit(v));
    EXPECT_TRUE(*some == v || (std::isnan(v) && std::isnan(*some)));
  }
  OptionalSeconds from_optional = std::optional<double>(2.5);
  EXPECT_EQ(*from_optional, 2.5);
  *from_optional *= 2;
  EXPECT_EQ(std::optional<double>(from_optional), std::optional<double>(5.0));
  from_optional = std::nullopt;
  EXPECT_EQ(std::optional<double>(from_optional), std::nullopt);
  EXPECT_EQ(OptionalSeconds(1.0), OptionalSeconds(1.0));
  EXPECT_FALSE(OptionalSeconds(1.0) == OptionalSeconds());
  EXPECT_EQ(sizeof(OptionalSeconds), sizeof(double));
}

TEST(OptionalPeriodic, CopiesItsFunctionAndComparesByValue) {
  Curve a = Curve::constant(1);
  EXPECT_FALSE(a.periodic);
  a.periodic = Periodic{Periodic::Shape::triangle, 0, 2, 4};
  Curve b = a;  // a deep copy: changing b leaves a alone
  b.periodic->max = 3;
  EXPECT_EQ(a.periodic->max, 2);
  EXPECT_FALSE(a == b);
  b.periodic->max = 2;
  EXPECT_TRUE(a == b);
  b.periodic.reset();
  EXPECT_FALSE(a == b);
  EXPECT_EQ(a.value_at(1), 1);  // the triangle at a quarter period
}

TEST(TargetName, ReadsLikeAStringAndEqualNamesShareOneCopy) {
  const TargetName jaw = "open_jaw";
  const TargetName again = std::string("open_") + "jaw";
  EXPECT_EQ(jaw, again);
  EXPECT_EQ(&jaw.str(), &again.str());
  EXPECT_EQ(jaw, "open_jaw");
  EXPECT_EQ(jaw + "!", "open_jaw!");
  std::map<std::string, int> by_name;
  by_name[jaw] = 1;
  EXPECT_EQ(by_name.count("open_jaw"), 1u);
  std::ostringstream out;
  out << jaw;
  EXPECT_EQ(out.str(), "open_jaw");
  EXPECT_TRUE(TargetName().empty());
  // More names in turn than the recent-names cache holds still intern to one copy each.
  for (int round = 0; round < 3; ++round)
    for (int i = 0; i < 20; ++i) {
      const TargetName a = "t" + std::to_string(i), b = "t" + std::to_string(i);
      EXPECT_EQ(&a.str(), &b.str());
    }
}

}  // namespace
}  // namespace fapc
