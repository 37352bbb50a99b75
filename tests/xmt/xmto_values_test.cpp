// What animate and set do to their FAP: SMIL's animation function (values, keyTimes, calcMode,
// from/to/by, additive, accumulate) and fill, checked as blended values on the timeline. Expected
// values were worked out by hand from SMIL Animation's rules (docs/xmt-omega.md, "Values"); the
// columns of warnings were counted with a script over the document line (offset of the attribute).
#include <gtest/gtest.h>

#include "xmto_test_helpers.hpp"

namespace fapc::xmt {
namespace {

using test::document;
using test::read_ok;
using test::value_at;

Timeline read_timeline(const std::string& body) { return read_ok(document(body)).timeline; }

TEST(XmtoValues, FromToIsLinearAndReplaces) {
  const Timeline t = read_timeline(R"(<animate attributeName="open_jaw" from="0" to="100" dur="2s"/>)");
  EXPECT_DOUBLE_EQ(value_at(t, "open_jaw", 0.5), 25);
  EXPECT_DOUBLE_EQ(value_at(t, "open_jaw", 1.5), 75);
  EXPECT_DOUBLE_EQ(value_at(t, "open_jaw", 2.5), 0);  // fill remove: back to neutral
  EXPECT_EQ(t.clips.at(0).blend, BlendMode::overwrite);
}

TEST(XmtoValues, ValuesAreSpreadEvenly) {
  // Three values over 2 s: 0 at 0, 100 at 1, 50 at 2.
  const Timeline t = read_timeline(R"(<animate attributeName="open_jaw" values="0;100;50" dur="2s"/>)");
  EXPECT_DOUBLE_EQ(value_at(t, "open_jaw", 0.5), 50);
  EXPECT_DOUBLE_EQ(value_at(t, "open_jaw", 1), 100);
  EXPECT_DOUBLE_EQ(value_at(t, "open_jaw", 1.5), 75);
}

TEST(XmtoValues, KeyTimesPlaceTheValues) {
  // 100 at 0.25 x 4 s = 1 s; then down to 50 at 4 s: at 2.5 s, 100 - 50 x 1.5 / 3 = 75.
  const Timeline t =
      read_timeline(R"(<animate attributeName="open_jaw" values="0;100;50" keyTimes="0;0.25;1" dur="4s"/>)");
  EXPECT_DOUBLE_EQ(value_at(t, "open_jaw", 0.5), 50);
  EXPECT_DOUBLE_EQ(value_at(t, "open_jaw", 1), 100);
  EXPECT_DOUBLE_EQ(value_at(t, "open_jaw", 2.5), 75);
}

TEST(XmtoValues, DiscreteGivesEachValueAnEqualShare) {
  // Four values over 4 s: each holds for 1 s.
  const Timeline t =
      read_timeline(R"(<animate attributeName="open_jaw" values="10;20;30;40" calcMode="discrete" dur="4s"/>)");
  EXPECT_DOUBLE_EQ(value_at(t, "open_jaw", 0.5), 10);
  EXPECT_DOUBLE_EQ(value_at(t, "open_jaw", 1), 20);
  EXPECT_DOUBLE_EQ(value_at(t, "open_jaw", 2.5), 30);
  EXPECT_DOUBLE_EQ(value_at(t, "open_jaw", 3.75), 40);
}

TEST(XmtoValues, DiscreteWithKeyTimesAndFromTo) {
  const Timeline t = read_timeline(
      R"(<par><animate attributeName="open_jaw" values="10;20" keyTimes="0;0.75" calcMode="discrete" dur="4s"/>)"
      R"(<animate attributeName="head_yaw" from="0" to="100" calcMode="discrete" dur="2s"/></par>)");
  EXPECT_DOUBLE_EQ(value_at(t, "open_jaw", 2.5), 10);
  EXPECT_DOUBLE_EQ(value_at(t, "open_jaw", 3), 20);
  EXPECT_DOUBLE_EQ(value_at(t, "head_yaw", 0.75), 0);  // from for the first half
  EXPECT_DOUBLE_EQ(value_at(t, "head_yaw", 1), 100);
}

TEST(XmtoValues, PacedSpacesTheValuesByDistance) {
  // Distances 100, 100, 50 of 250 over 5 s: the values sit at 0, 2, 4 and 5 s.
  const Timeline t =
      read_timeline(R"(<animate attributeName="open_jaw" values="0;100;0;50" calcMode="paced" dur="5s"/>)");
  EXPECT_DOUBLE_EQ(value_at(t, "open_jaw", 1), 50);
  EXPECT_DOUBLE_EQ(value_at(t, "open_jaw", 2), 100);
  EXPECT_DOUBLE_EQ(value_at(t, "open_jaw", 3), 50);
  EXPECT_DOUBLE_EQ(value_at(t, "open_jaw", 4.5), 25);
}

TEST(XmtoValues, PacedOverNoDistanceIsConstant) {
  const Timeline t = read_timeline(R"(<animate attributeName="open_jaw" values="7;7;7" calcMode="paced" dur="2s"/>)");
  EXPECT_DOUBLE_EQ(value_at(t, "open_jaw", 1.25), 7);
}

TEST(XmtoValues, ByAloneAddsToWhatIsThere) {
  // An additive ramp 0..100 over 2 s plus by=30 over 2 s: at 1 s, 50 + 15.
  const Timeline t =
      read_timeline(R"(<par><animate attributeName="open_jaw" from="0" to="100" dur="2s" additive="sum"/>)"
                    R"(<animate attributeName="open_jaw" by="30" dur="2s"/></par>)");
  EXPECT_DOUBLE_EQ(value_at(t, "open_jaw", 1), 65);
  EXPECT_EQ(t.clips.at(1).blend, BlendMode::add);
}

TEST(XmtoValues, FromByRampsFromFromToFromPlusBy) {
  const Timeline t = read_timeline(R"(<animate attributeName="open_jaw" from="10" by="30" dur="1s"/>)");
  EXPECT_DOUBLE_EQ(value_at(t, "open_jaw", 0.5), 25);
  EXPECT_EQ(t.clips.at(0).blend, BlendMode::overwrite);
}

TEST(XmtoValues, ToAnimationStartsWhereTheFrozenOneStopped) {
  // The nod of corpus/xmto/nod-and-smile.xmt: up to 3400 in 0.25 s and frozen, then a to-animation
  // back to 0.
  const Timeline t =
      read_timeline(R"(<seq><animate attributeName="head_pitch" from="0" to="3400" dur="0.25s" fill="freeze"/>)"
                    R"(<animate attributeName="head_pitch" to="0" dur="0.25s" fill="freeze"/></seq>)");
  EXPECT_DOUBLE_EQ(value_at(t, "head_pitch", 0.25), 3400);
  EXPECT_DOUBLE_EQ(value_at(t, "head_pitch", 0.375), 1700);
  EXPECT_DOUBLE_EQ(value_at(t, "head_pitch", 1), 0);
}

TEST(XmtoValues, ToAnimationStartsFromTheValueUnderneath) {
  // An additive ramp 0..100 over 4 s; at 2 s (value 50) a to-animation goes to 0 in 1 s and
  // replaces it; after 3 s the ramp shows again (87.5 at 3.5 s).
  const Timeline t =
      read_timeline(R"(<par><animate attributeName="open_jaw" from="0" to="100" dur="4s" additive="sum"/>)"
                    R"(<animate attributeName="open_jaw" to="0" begin="2s" dur="1s"/></par>)");
  EXPECT_DOUBLE_EQ(value_at(t, "open_jaw", 2.5), 25);
  EXPECT_DOUBLE_EQ(value_at(t, "open_jaw", 3.5), 87.5);
}

TEST(XmtoValues, RepeatedToAnimationStartsFromTheUnderlyingValueEachTime) {
  // SMIL: each run of a to-animation starts from the value without it, here a set of 40.
  const Timeline t =
      read_timeline(R"(<par><set attributeName="open_jaw" to="40" dur="4s"/>)"
                    R"(<animate attributeName="open_jaw" to="0" dur="1s" repeatCount="2" begin="1s"/></par>)");
  EXPECT_DOUBLE_EQ(value_at(t, "open_jaw", 1.5), 20);
  EXPECT_DOUBLE_EQ(value_at(t, "open_jaw", 2.5), 20);
}

TEST(XmtoValues, AdditiveAnimationsAddAndReplaceHidesThem) {
  const Timeline t =
      read_timeline(R"(<par><animate attributeName="open_jaw" from="0" to="100" dur="2s" additive="sum"/>)"
                    R"(<animate attributeName="open_jaw" from="0" to="50" dur="2s" additive="sum"/>)"
                    R"(<set attributeName="open_jaw" to="20" begin="0.5s" dur="0.5s"/></par>)");
  EXPECT_DOUBLE_EQ(value_at(t, "open_jaw", 0.25), 18.75);
  EXPECT_DOUBLE_EQ(value_at(t, "open_jaw", 0.75), 20);
  EXPECT_DOUBLE_EQ(value_at(t, "open_jaw", 1), 75);
}

TEST(XmtoValues, TheLaterReplaceWins) {
  // b began later: it wins over a; c and d begin together: the later in the document wins.
  const Timeline t = read_timeline(R"(<par><set attributeName="open_jaw" to="10" dur="2s"/>)"
                                   R"(<set attributeName="open_jaw" to="20" begin="1s" dur="2s"/>)"
                                   R"(<set attributeName="head_yaw" to="30" dur="1s"/>)"
                                   R"(<set attributeName="head_yaw" to="40" dur="1s"/></par>)");
  EXPECT_DOUBLE_EQ(value_at(t, "open_jaw", 0.5), 10);
  EXPECT_DOUBLE_EQ(value_at(t, "open_jaw", 1.5), 20);
  EXPECT_DOUBLE_EQ(value_at(t, "head_yaw", 0.5), 40);
}

TEST(XmtoValues, AccumulateBuildsOnTheLastValue) {
  const Timeline t = read_timeline(
      R"(<par><animate attributeName="open_jaw" from="0" to="10" dur="1s" repeatCount="3" accumulate="sum" fill="freeze"/>)"
      R"(<animate attributeName="head_yaw" from="0" to="10" dur="1s" repeatCount="3"/></par>)");
  EXPECT_DOUBLE_EQ(value_at(t, "open_jaw", 0.5), 5);
  EXPECT_DOUBLE_EQ(value_at(t, "open_jaw", 1.5), 15);
  EXPECT_DOUBLE_EQ(value_at(t, "open_jaw", 2.5), 25);
  EXPECT_DOUBLE_EQ(value_at(t, "open_jaw", 3), 30);   // frozen at the end of the third run
  EXPECT_DOUBLE_EQ(value_at(t, "head_yaw", 2.5), 5);  // without accumulate each run restarts
}

TEST(XmtoValues, FreezeAfterAFractionalRepeatKeepsTheValueWhereItWasCut) {
  // 1.5 runs of 2 s: cut halfway through the second run, at 50; frozen from 3 s on.
  const Timeline t =
      read_timeline(R"(<animate attributeName="open_jaw" from="0" to="100" dur="2s" repeatCount="1.5" fill="freeze"/>)"
                    R"(<set attributeName="head_yaw" to="1" dur="2s"/>)");
  EXPECT_DOUBLE_EQ(value_at(t, "open_jaw", 4), 50);
}

TEST(XmtoValues, SetIsAConstantThatReplaces) {
  const Timeline t = read_timeline(R"(<set attributeName="open_jaw" to="20" dur="1s"/>)");
  ASSERT_EQ(t.clips.size(), 1u);
  EXPECT_EQ(t.clips[0].curve, Curve::constant(20));
  EXPECT_EQ(t.clips[0].blend, BlendMode::overwrite);
}

TEST(XmtoValues, AnIndefiniteSimpleDurationHoldsTheFirstValue) {
  // No dur: SMIL does not interpolate over an indefinite simple duration.
  const Timeline t = read_timeline(R"(<par><animate attributeName="open_jaw" from="10" to="100" end="2s"/></par>)");
  EXPECT_DOUBLE_EQ(value_at(t, "open_jaw", 1.5), 10);
}

TEST(XmtoValues, TargetsByNameNumberBifsNameAndWeight) {
  const auto doc = read_ok(document(
      R"(<par><set attributeName="3" to="1" dur="1s"/><set attributeName="fap4" to="1" dur="1s"/>)"
      R"(<set attributeName="FAP5" to="1" dur="1s"/><set attributeName="stretch_l_corner" to="1" dur="1s"/>)"
      R"(<set attributeName="lower_b_lip_lm" to="1" dur="1s"/><set attributeName="viseme.pp" to="1" dur="1s"/>)"
      R"(<set attributeName="expression.JOY" to="1" dur="1s"/>)"
      R"(<set attributeName="stretch_r_cornerlip" to="1" dur="1s"/></par>)"));
  std::vector<std::string> targets;
  for (const Clip& clip : doc.timeline.clips) targets.push_back(clip.target);
  EXPECT_EQ(targets,
            (std::vector<std::string>{"open_jaw", "lower_t_midlip", "raise_b_midlip", "stretch_l_cornerlip",
                                      "raise_b_lip_lm", "viseme.PP", "expression.joy", "stretch_r_cornerlip"}));
  EXPECT_EQ(test::messages(doc.warnings),
            std::vector<std::string>{"t.xmt:3:346: warning: 'stretch_r_cornerlip' is read as FAP 7 (ISO/IEC "
                                     "14496-2 naming); in BIFS naming it is FAP 54: write the number to say which"});
}

TEST(XmtoValues, IgnoredCombinationsAreReported) {
  const auto doc = read_ok(
      document(R"(<par><animate attributeName="open_jaw" from="1" values="0;1" dur="1s"/>)"
               R"(<animate attributeName="open_jaw" to="1" by="2" dur="1s"/>)"
               R"(<animate attributeName="open_jaw" to="1" additive="sum" accumulate="sum" dur="1s"/>)"
               R"(<animate attributeName="open_jaw" by="1" additive="replace" dur="1s"/>)"
               R"(<animate attributeName="open_jaw" values="0;1" keyTimes="0;1" calcMode="paced" dur="1s"/></par>)"));
  EXPECT_EQ(test::messages(doc.warnings),
            (std::vector<std::string>{"t.xmt:3:40: warning: from is ignored: values is given",
                                      "t.xmt:3:113: warning: by is ignored: to is given",
                                      "t.xmt:3:171: warning: additive is ignored: a to animation replaces",
                                      "t.xmt:3:186: warning: accumulate is ignored: a to animation does not accumulate",
                                      "t.xmt:3:254: warning: additive is ignored: a by animation adds",
                                      "t.xmt:3:330: warning: keyTimes is ignored with calcMode paced"}));
}

}  // namespace
}  // namespace fapc::xmt
