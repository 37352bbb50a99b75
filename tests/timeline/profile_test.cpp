#include <gtest/gtest.h>

#include "fapc/transcoder/profile.hpp"

namespace fapc {
namespace {

TEST(Profile, DefaultCoversThePapersNames) {
  for (const char* name :
       {"jaw", "eyelid_left", "eyelid_right", "head_rot_x", "head_rot_y", "head_rot_z", "lookat_x", "lookat_y"}) {
    EXPECT_FALSE(resolve_target(name, default_profile()).empty()) << name;
  }
  EXPECT_EQ(resolve_target("jaw", default_profile()), (std::vector<FapContribution>{{3, 1024}}));
  EXPECT_EQ(resolve_target("lookat_x", default_profile()).size(), 2u);
}

TEST(Profile, FapNamesNumbersAndWeightTargetsNeedNoProfile) {
  const Profile empty;
  EXPECT_EQ(resolve_target("open_jaw", empty), (std::vector<FapContribution>{{3, 1}}));
  EXPECT_EQ(resolve_target("fap48", empty), (std::vector<FapContribution>{{48, 1}}));
  EXPECT_EQ(resolve_target("viseme.PP", empty), (std::vector<FapContribution>{{1, 1}}));
  EXPECT_EQ(resolve_target("expression.Joy", empty), (std::vector<FapContribution>{{2, 1}}));
  EXPECT_TRUE(resolve_target("viseme.zz", empty).empty());
  EXPECT_TRUE(resolve_target("jaw", empty).empty());
}

TEST(Profile, ParsesNamesOnSeveralLines) {
  const auto p = parse_profile("# comment\nsmile lip_corner 1\r\nsmile 59 2  # both corners\n", "p");
  ASSERT_FALSE(p.ok());  // lip_corner is not a FAP name
  EXPECT_EQ(format_diagnostic(p.error()).substr(0, 33), "p:2:7: error: unknown FAP name 'l");
  const auto q = parse_profile("smile stretch_l_cornerlip 1\r\nsmile 59 2  # both corners\n", "q");
  ASSERT_TRUE(q.ok());
  EXPECT_EQ(resolve_target("smile", *q), (std::vector<FapContribution>{{6, 1}, {59, 2}}));
}

TEST(Profile, RejectsBadLinesAtTheirColumn) {
  const auto fields = parse_profile("jaw open_jaw\n", "p");
  ASSERT_FALSE(fields.ok());
  EXPECT_EQ(format_diagnostic(fields.error()), "p:1:5: error: expected 'name fap scale', found 2 fields");
  const auto scale = parse_profile("jaw open_jaw x1\n", "p");
  ASSERT_FALSE(scale.ok());
  EXPECT_EQ(format_diagnostic(scale.error()), "p:1:14: error: the scale 'x1' is not a number");
  const auto standard = parse_profile("open_jaw head_yaw 1\n", "p");
  ASSERT_FALSE(standard.ok());
  EXPECT_EQ(format_diagnostic(standard.error()),
            "p:1:1: error: 'open_jaw' is a standard FAP name; a profile maps other names");
  const auto viseme = parse_profile("v viseme 1\n", "p");
  ASSERT_FALSE(viseme.ok());
  EXPECT_EQ(viseme.error().where.column, 3);
}

}  // namespace
}  // namespace fapc
