// Every rule of docs/mimic.md, "Timing and values", with values worked out by hand.
#include <cmath>
#include <numbers>

#include "mimic_test_support.hpp"

namespace fapc {
namespace {

using test::timeline_of;

double at(const Timeline& t, const std::string& target, double time) {
  return TimelineEvaluator(t).value_at(target, time);
}

std::vector<std::pair<double, double>> spans(const Timeline& t) {
  std::vector<std::pair<double, double>> out;
  for (const Clip& c : t.clips) out.emplace_back(c.begin, c.end);
  return out;
}
using Spans = std::vector<std::pair<double, double>>;

TEST(MimicSemantics, SequenceChainsAndFadePhases) {
  // Fade 1: [0, 4) rising over 1 s to 0.5, holding 2 s, falling over 1 s. Fade 2: [4, 6).
  const Timeline t = timeline_of("main { jaw <in=1,hold=2,out=1,value=0.5>; jaw <in=2,value=1>; }");
  EXPECT_EQ(spans(t), (Spans{{0, 4}, {4, 6}}));
  EXPECT_DOUBLE_EQ(at(t, "jaw", 0.5), 0.25);    // linear, half way up
  EXPECT_DOUBLE_EQ(at(t, "jaw", 2), 0.5);       // plateau
  EXPECT_DOUBLE_EQ(at(t, "jaw", 3.25), 0.375);  // a quarter into the fall: 0.5 - 0.5/4
  EXPECT_DOUBLE_EQ(at(t, "jaw", 5), 0.5);       // second fade half way up
  EXPECT_DOUBLE_EQ(at(t, "jaw", 6.5), 0);       // after everything: neutral
}

TEST(MimicSemantics, FadingFunctionsAtExactFractions) {
  // in = 4, value 2: at t = 1 (u = 1/4) and t = 2 (u = 1/2).
  const double q = (1 - std::cos(std::numbers::pi / 4)) / 2;
  EXPECT_NEAR(at(timeline_of("main { jaw <in=4,value=2,sin>; }"), "jaw", 1), 2 * q, 1e-12);
  EXPECT_NEAR(at(timeline_of("main { jaw <in=4,value=2,sin>; }"), "jaw", 2), 1, 1e-12);
  EXPECT_NEAR(at(timeline_of("main { jaw <in=4,value=2,log>; }"), "jaw", 2), 2 * std::log(5.5) / std::log(10.0), 1e-12);
  EXPECT_NEAR(at(timeline_of("main { jaw <in=4,value=2,exp>; }"), "jaw", 1), 2 * (std::pow(10.0, 0.25) - 1) / 9, 1e-12);
  // The fall mirrors the rise: value + (0 - value) f(u); with exp at u = 1/2: 2 - 2 (sqrt 10 - 1)/9.
  EXPECT_NEAR(at(timeline_of("main { jaw <out=4,value=2,exp>; }"), "jaw", 2), 2 - 2 * (std::sqrt(10.0) - 1) / 9, 1e-12);
}

TEST(MimicSemantics, LeftShiftsAndNegativeLeftOverlaps) {
  const Timeline t = timeline_of(
      "main { jaw <in=2,value=1>; head_rot_x <left=-1,in=2,value=1>; "
      "jaw <left=3,in=1,value=1>; }");
  // Second starts at 2 - 1 = 1; third at its predecessor's end 3, plus 3.
  EXPECT_EQ(spans(t), (Spans{{0, 2}, {1, 3}, {6, 7}}));
}

TEST(MimicSemantics, ParallelRightAlignmentAndStretching) {
  // Reference end 5 (the fade). right: ends at 5; right=-1: ends at 4; the periodic child
  // without duration spans [0, 5).
  const Timeline t = timeline_of(
      "main [ jaw <in=5,value=1>; head_rot_x <in=1,value=1,right>; "
      "head_rot_y <in=1,value=1,right=-1>; eyelid_left <min=0,max=1,period=2>; ]");
  EXPECT_EQ(spans(t), (Spans{{0, 5}, {4, 5}, {3, 4}, {0, 5}}));
  // The periodic starts at min and reaches max half a period later (sin by default).
  EXPECT_DOUBLE_EQ(at(t, "eyelid_left", 0), 0);
  EXPECT_DOUBLE_EQ(at(t, "eyelid_left", 1), 1);
  EXPECT_DOUBLE_EQ(at(t, "eyelid_left", 0.5), 0.5);
}

TEST(MimicSemantics, LinearPeriodicIsATriangle) {
  const Timeline t = timeline_of("main { jaw <min=1,max=3,freq=0.25,linear,duration=8>; }");
  EXPECT_DOUBLE_EQ(at(t, "jaw", 1), 2);  // a quarter period: half way up
  EXPECT_DOUBLE_EQ(at(t, "jaw", 2), 3);
  EXPECT_DOUBLE_EQ(at(t, "jaw", 3), 2);
  EXPECT_DOUBLE_EQ(at(t, "jaw", 4), 1);
  EXPECT_DOUBLE_EQ(at(timeline_of("main { jaw <min=1,max=3,freq=0.25,period=4,duration=8>; }"), "jaw", 2), 3);
}

TEST(MimicSemantics, TimeValueListStartsAtItsFirstTime) {
  const Timeline t = timeline_of("main { jaw <in=1,value=1>; jaw ( 0.5 1.5 2.5; 0.2 0.4 0; ) }");
  // The list runs from its action's start 1; its curve starts at 1 + 0.5 and lasts to 1 + 2.5.
  EXPECT_EQ(spans(t), (Spans{{0, 1}, {1.5, 3.5}}));
  EXPECT_DOUBLE_EQ(at(t, "jaw", 1.25), 0);  // absent before its first time
  EXPECT_DOUBLE_EQ(at(t, "jaw", 2), 0.3);
}

TEST(MimicSemantics, BlendPrecedence) {
  // add: 0.25 + 0.5; average: (0.25 + 0.5 + 0.75) / 3; overwrite beats both, the later begin wins.
  EXPECT_DOUBLE_EQ(at(timeline_of("main [ jaw <hold=2,value=0.25>; jaw <hold=2,value=0.5>; ]"), "jaw", 1), 0.75);
  EXPECT_DOUBLE_EQ(at(timeline_of("main [ jaw <hold=2,value=0.25>; jaw <hold=2,value=0.5,average>; "
                                  "jaw <hold=2,value=0.75>; ]"),
                      "jaw", 1),
                   0.5);
  const Timeline o = timeline_of(
      "main [ jaw <hold=4,value=0.25,overwrite>; jaw <left=1,hold=2,value=0.5,overwrite>; "
      "jaw <hold=4,value=0.75,average>; ]");
  EXPECT_DOUBLE_EQ(at(o, "jaw", 0.5), 0.25);
  EXPECT_DOUBLE_EQ(at(o, "jaw", 2), 0.5);
  EXPECT_DOUBLE_EQ(at(o, "jaw", 3.5), 0.25);
}

TEST(MimicSemantics, GroupAndMainBlendApplyToClipsWithoutTheirOwn) {
  const Timeline t = timeline_of(
      "main <average> { <overwrite> [ jaw <hold=1,value=1>; jaw <hold=1,value=2,add>; ] "
      "jaw <hold=1,value=3>; }");
  ASSERT_EQ(t.clips.size(), 3u);
  EXPECT_EQ(t.clips[0].blend, BlendMode::overwrite);
  EXPECT_EQ(t.clips[1].blend, BlendMode::add);
  EXPECT_EQ(t.clips[2].blend, BlendMode::average);
}

TEST(MimicSemantics, ConnectEndsAtTheNextClipsValueAtItsBegin) {
  // The fade ends at 0.2, the list's first value. Half way through its fall (linear): 0.6.
  const Timeline t = timeline_of("main { jaw <in=1,out=2,value=1,connect>; jaw ( 0 1; 0.2 0.4; ) }");
  EXPECT_DOUBLE_EQ(at(t, "jaw", 2), 0.6);
  EXPECT_DOUBLE_EQ(TimelineEvaluator(t).value_at("jaw", 3, true), 0.2);
  // Connected to a fade, whose value at its begin is the neutral 0: the fall ends at 0.
  const Timeline f = timeline_of("main { jaw <in=1,out=2,value=1,connect>; jaw <in=1,value=0.5>; }");
  EXPECT_DOUBLE_EQ(at(f, "jaw", 2), 0.5);
  // No next clip: 0. connect=x: x.
  EXPECT_DOUBLE_EQ(at(timeline_of("main { jaw <out=2,value=1,connect>; }"), "jaw", 1), 0.5);
  EXPECT_DOUBLE_EQ(at(timeline_of("main { jaw <out=2,value=1,connect=0.5>; }"), "jaw", 1), 0.75);
}

TEST(MimicSemantics, MacrosExpandWhereUsedWithTheirParameters) {
  const Timeline t = timeline_of(
      "def blink { eyelid_left <in=0.5,out=0.5,value=1>; } "
      "main { blink; blink <left=1,overwrite>; }");
  EXPECT_EQ(spans(t), (Spans{{0, 1}, {2, 3}}));
  EXPECT_EQ(t.clips[1].blend, BlendMode::overwrite);
}

TEST(MimicSemantics, ExpressionsAmplifyEveryParameter) {
  const Timeline t = timeline_of("defxpr smile \"s.xpr\" main { smile <in=2,value=0.5>; }",
                                 {{"s.xpr", "# a smile\nraise_l_cornerlip 120\njaw 0.2\n"}});
  // The expression becomes a facial state in FAP units (jaw 0.2 x 1024 = 204.8 -> 205 on
  // open_jaw), amplified by the Algebra: round(0.5 x 120) = 60, round(0.5 x 205) = 103 (half
  // away from zero). Half way up the fade: 30 and 51.5.
  ASSERT_EQ(t.clips.size(), 2u);
  EXPECT_DOUBLE_EQ(at(t, "raise_l_cornerlip", 1), 30);
  EXPECT_DOUBLE_EQ(at(t, "open_jaw", 1), 51.5);
}

TEST(MimicSemantics, CommentsAndOptionalSemicolons) {
  const Timeline t = timeline_of("// a line comment\nmain /* a block\n comment */ { jaw <hold=1,value=1> }");
  EXPECT_EQ(spans(t), (Spans{{0, 1}}));
}

TEST(MimicSemantics, OutOfRangeValuesWarnAtTheNumber) {
  // jaw x 1024: 5 -> 5120 beyond open_jaw's 4320.
  const Result<MimicProgram> p = test::compile("main { jaw <hold=1,value=5>; }");
  ASSERT_TRUE(p.ok());
  ASSERT_EQ(p->warnings.size(), 1u);
  EXPECT_EQ(format_diagnostic(p->warnings[0]),
            "t.mimic:1:26: warning: value 5 of 'jaw' is 5120 in open_jaw units, outside "
            "-4320..4320 (it will be clamped)");
}

TEST(MimicSemantics, Table2ProgramSchedulesAsWorkedOutByHand) {
  const std::string source = test::read_text(test::corpus_dir() + "/mimic/table2.mimic");
  const Timeline t = timeline_of(source);
  // Worked out from Mimic Table 2 (line: span): 3: [0,132) 5: [0,30) 6: [30,35) 9: [35,72)
  // 11: [50,60) 13: [45,65) 15: [72,97) 17: [97,122) 19: [107,117) 21: [122,132) 28: [132,152)
  // 29: [132.1,152) 33: [152,262) 35: [152,182) 36: [182,187) 38: [197,212) 39: [212,237)
  // 40: [237,262) 42: [162,252).
  std::map<int, std::pair<double, double>> by_line;
  for (const Clip& c : t.clips) by_line[c.source.line] = {c.begin, c.end};
  const std::map<int, std::pair<double, double>> expected{
      {3, {0, 132}},    {5, {0, 30}},       {6, {30, 35}},    {9, {35, 72}},    {11, {50, 60}},
      {13, {45, 65}},   {15, {72, 97}},     {17, {97, 122}},  {19, {107, 117}}, {21, {122, 132}},
      {28, {132, 152}}, {29, {132.1, 152}}, {33, {152, 262}}, {35, {152, 182}}, {36, {182, 187}},
      {38, {197, 212}}, {39, {212, 237}},   {40, {237, 262}}, {42, {162, 252}}};
  EXPECT_EQ(by_line, expected);
  // connect: line 5 ends at line 6's first value 0.2; line 17 at line 21's min 0.05.
  EXPECT_DOUBLE_EQ(TimelineEvaluator(t).value_at("jaw", 30, true), 0.2);
  EXPECT_DOUBLE_EQ(t.clips[7].curve.keys.back().value, 0.05);
}

}  // namespace
}  // namespace fapc
