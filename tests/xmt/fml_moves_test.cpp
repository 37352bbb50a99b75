// FML moves (docs/fml.md, "Moves") against values worked out by hand: each move ramps its
// target from the current value to its own and holds it; expr onto FAP 2 weights (val % of 63),
// hdmv onto head rotation in angle units (1 degree = 1e5 * pi / 180 = 1745.33 AU) within the
// model's ranges, fap by number or name, param through the profile, talk onto visemes.
#include "fml_test_helpers.hpp"

namespace fapc::xmt {
namespace {

using namespace fml_test;
using Keys = std::vector<std::pair<double, double>>;

constexpr double kDegree = 1745.3292519943295;

TEST(FmlMoves, ExprRampsItsExpressionWeightFromTheCurrentValue) {
  // smile 80 % = 50.4 over 1 s, then smile 50 % = 31.5 from 50.4; type 3 is anger.
  const auto doc =
      read_ok(in_action("<expr type=\"smile\" val=\"80\"/><expr type=\"joy\" val=\"50\" duration=\"2s\"/>"
                        "<expr type=\"3\"/>"));
  ASSERT_EQ(doc.timeline.clips.size(), 3u);
  EXPECT_EQ(doc.timeline.clips[0].target, "expression.joy");
  EXPECT_EQ(keys(doc.timeline.clips[0]), (Keys{{0, 0}, {1, 50.4}}));
  EXPECT_EQ(keys(doc.timeline.clips[1]), (Keys{{0, 50.4}, {2, 31.5}}));
  EXPECT_EQ(doc.timeline.clips[2].target, "expression.anger");
  EXPECT_EQ(keys(doc.timeline.clips[2]), (Keys{{0, 0}, {1, 63}}));  // val defaults to 100 %
  for (const Clip& clip : doc.timeline.clips) {
    EXPECT_EQ(clip.blend, BlendMode::overwrite);
    EXPECT_EQ(clip.fill, Fill::freeze);
  }
}

TEST(FmlMoves, NormalReturnsEveryExpressionToZero) {
  const auto doc =
      read_ok(in_action("<par><expr type=\"smile\" val=\"80\"/><expr type=\"anger\" val=\"50\" duration=\"2s\"/></par>"
                        "<expr type=\"normal\" duration=\"0.5s\"/>"));
  ASSERT_EQ(doc.timeline.clips.size(), 4u);
  // The par ends at 2; at 2 joy holds 50.4, anger has reached 31.5.
  expect_spans(doc.timeline, Spans{{"expression.joy", 0, 1},
                                   {"expression.anger", 0, 2},
                                   {"expression.anger", 2, 2.5},
                                   {"expression.joy", 2, 2.5}});
  EXPECT_EQ(keys(doc.timeline.clips[2]), (Keys{{0, 31.5}, {0.5, 0}}));
  EXPECT_EQ(keys(doc.timeline.clips[3]), (Keys{{0, 50.4}, {0.5, 0}}));
}

TEST(FmlMoves, ExprOutsideZeroToHundredIsClampedWithAWarning) {
  const auto doc = read_ok(in_action("<expr type=\"fear\" val=\"150\"/>"));
  EXPECT_EQ(keys(doc.timeline.clips[0]), (Keys{{0, 0}, {1, 63}}));
  EXPECT_EQ(messages(doc.warnings),
            (std::vector<std::string>{"t.fml:3:34: warning: expression val 150 is outside 0-100 (%) and was clamped"}));
}

TEST(FmlMoves, HdmvTurnsTheHeadInAngleUnitsWithinTheModelsRange) {
  // yaw 30 within left 60: 30 degrees. pitch (1) -20 with up 10: -10. roll 5: no range, 5.
  const auto doc =
      read_ok(in_action("<hdmv type=\"yaw\" val=\"30\"/><hdmv type=\"1\" val=\"-20\"/><hdmv dir=\"roll\" val=\"5\"/>",
                        "<range type=\"left\" val=\"60\"/><range type=\"up\" val=\"10\"/>"));
  ASSERT_EQ(doc.timeline.clips.size(), 3u);
  expect_spans(doc.timeline, Spans{{"head_yaw", 0, 1}, {"head_pitch", 1, 2}, {"head_roll", 2, 3}});
  EXPECT_DOUBLE_EQ(doc.timeline.clips[0].curve.keys.back().value, 30 * kDegree);
  EXPECT_DOUBLE_EQ(doc.timeline.clips[1].curve.keys.back().value, -10 * kDegree);
  EXPECT_DOUBLE_EQ(doc.timeline.clips[2].curve.keys.back().value, 5 * kDegree);
  EXPECT_EQ(messages(doc.warnings),
            (std::vector<std::string>{
                "t.fml:3:58: warning: head movement of -20 degrees is beyond the model's range and was clamped",
                "t.fml:3:75: warning: dir is read as type, the paper's spelling"}));
}

TEST(FmlMoves, AnUnknownHeadMovementWaitsInItsPlace) {
  // The published sample's hdmv type="surprise": reported; the next move still starts at 1 s.
  const auto doc = read_ok(in_action("<hdmv type=\"surprise\"/><fap type=\"3\" val=\"5\"/>"));
  expect_spans(doc.timeline, Spans{{"open_jaw", 1, 2}});
  EXPECT_EQ(messages(doc.warnings),
            (std::vector<std::string>{
                "t.fml:3:22: warning: head movement type 'surprise' is not yaw, pitch, roll or 0-2: it waits"}));
}

TEST(FmlMoves, FapTakesANumberOrAName) {
  const auto doc = read_ok(in_action("<fap type=\"31\" val=\"120\"/><fap type=\"raise_l_i_eyebrow\" val=\"-40\"/>"));
  expect_spans(doc.timeline, Spans{{"raise_l_i_eyebrow", 0, 1}, {"raise_l_i_eyebrow", 1, 2}});
  EXPECT_EQ(keys(doc.timeline.clips[1]), (Keys{{0, 120}, {1, -40}}));
}

TEST(FmlMoves, ParamGoesThroughTheProfile) {
  // jaw is in the default profile; eye-wink (the paper's example) is not, and waits.
  const auto doc = read_ok(in_action("<param type=\"eye-wink\"/><param type=\"jaw\" val=\"0.5\"/>"));
  expect_spans(doc.timeline, Spans{{"jaw", 1, 2}});
  ASSERT_EQ(doc.warnings.size(), 1u);
  EXPECT_NE(doc.warnings[0].message.find("unknown animation parameter 'eye-wink'"), std::string::npos)
      << doc.warnings[0].message;
  Profile wink;
  wink.parameters["eye-wink"] = {{19, 1000}, {21, 1000}};
  FmlOptions options;
  options.profile = &wink;
  EXPECT_EQ(spans(read_ok(in_action("<param type=\"eye-wink\" val=\"1\"/>"), options).timeline),
            (Spans{{"eye-wink", 0, 1}}));
}

// The letter table's and the .pho file's own timing, without the coarticulation's overlaps.
FmlOptions exact_spans() {
  FmlOptions options;
  options.coarticulation = Coarticulation{0, 0};
  return options;
}

TEST(FmlMoves, TalkSaysOneVisemePerLetterGroupAtTwelvePerSecond) {
  // "Hi, Bob": h (no shape), i = ih; ',' two silent slots; ' ' one; B = PP, o = oh, b = PP.
  // Seven slots of 1/12 s: ih [0, 1), PP [4, 5), oh [5, 6), PP [6, 7) in twelfths.
  const auto doc = read_ok(in_action("<talk>Hi, Bob</talk>"), exact_spans());
  const double s = 1.0 / 12;
  expect_spans(
      doc.timeline,
      Spans{
          {"viseme.ih", 0, s}, {"viseme.PP", 4 * s, 5 * s}, {"viseme.oh", 5 * s, 6 * s}, {"viseme.PP", 6 * s, 7 * s}});
  EXPECT_DOUBLE_EQ(doc.timeline.explicit_end.value_or(0), 7 * s);
  EXPECT_EQ(doc.timeline.clips[0].curve.value_at(s / 2), 63);
}

TEST(FmlMoves, TalkWithADurationIsStretchedOverIt) {
  // "Hello": E, nn (ll said once), oh: three slots over 0.6 s.
  const auto doc = read_ok(in_action("<talk duration=\"0.6s\">Hello</talk>"), exact_spans());
  expect_spans(doc.timeline, Spans{{"viseme.E", 0, 0.2}, {"viseme.nn", 0.2, 0.4}, {"viseme.oh", 0.4, 0.6}});
}

TEST(FmlMoves, TalkFileReadsMbrolaPhonemes) {
  // _ 100 ms silence; h 50 ms has no shape; @ 80 ms = E; l 60 ms = nn; @U 120 ms = oh (by its first vowel).
  FmlOptions options = exact_spans();
  options.read_file = [](const std::string& path) -> Result<std::string> {
    EXPECT_EQ(path, "hello.pho");
    return std::string("; hello\n_ 100\nh 50\n@ 80 50 120\nl 60\n@U 120 0 110 100 90\n_ 40\n");
  };
  const auto doc = read_ok(in_action("<talk file=\"hello.pho\"/>"), options);
  expect_spans(doc.timeline, Spans{{"viseme.E", 0.15, 0.23}, {"viseme.nn", 0.23, 0.29}, {"viseme.oh", 0.29, 0.41}});
  EXPECT_DOUBLE_EQ(doc.timeline.explicit_end.value_or(0), 0.45);
  EXPECT_EQ(doc.phoneme_files, (std::vector<std::string>{"hello.pho"}));
}

TEST(FmlMoves, UnknownPhonemesAreSilentWithOneWarningEach) {
  FmlOptions options = exact_spans();
  options.read_file = [](const std::string&) -> Result<std::string> { return std::string("Y 100\np 50\nY 100\n"); };
  const auto doc = read_ok(in_action("<talk file=\"x.pho\"/>"), options);
  expect_spans(doc.timeline, Spans{{"viseme.PP", 0.1, 0.15}});
  EXPECT_EQ(
      messages(doc.warnings),
      (std::vector<std::string>{"x.pho:1:1: warning: phoneme 'Y' has no MPEG-4 viseme and is treated as silence"}));
}

TEST(FmlMoves, NeighbouringVisemesCrossFadeAndSilenceReturnsToNeutral) {
  // "Hello" by the letter table (E, nn, oh, 1/12 s each) with the default rule: a 60 ms fade
  // centred on each boundary, capped at half of each side (1/24 s here).
  const auto doc = read_ok(in_action("<talk>Hello</talk>"));
  ASSERT_EQ(doc.timeline.clips.size(), 3u);
  const double s = 1.0 / 12;
  const Clip& e = doc.timeline.clips[0];
  const Clip& nn = doc.timeline.clips[1];
  EXPECT_NEAR(nn.begin, s - 0.03, 1e-9);  // nn fades in over [s - 30 ms, s + 30 ms] ...
  EXPECT_NEAR(e.end, s + 0.03, 1e-9);     // ... while E fades out over the same
  EXPECT_NEAR(e.curve.value_at(s - e.begin), 31.5, 1e-9);
  EXPECT_NEAR(nn.curve.value_at(s - nn.begin), 31.5, 1e-9);
  const Clip& oh = doc.timeline.clips[2];
  EXPECT_NEAR(oh.curve.value_at(oh.end - oh.begin), 0, 1e-9);  // back to neutral after the word
  EXPECT_NEAR(oh.end, 3 * s + 0.03, 1e-9);
  ASSERT_EQ(doc.warnings.size(), 1u);  // no engine given: the letter table, said so
  EXPECT_EQ(doc.warnings[0].severity, Severity::warning);
}

TEST(FmlMoves, ATalkFileOtherThanPhonemesIsSilentWithAWarning) {
  const auto doc = read_ok(in_action("<talk file=\"hello.wav\" duration=\"2s\"/>"));
  EXPECT_TRUE(doc.timeline.clips.empty());
  EXPECT_EQ(doc.timeline.explicit_end, 2);
  ASSERT_EQ(doc.warnings.size(), 1u);
  EXPECT_EQ(doc.warnings[0].where.column, 22);
}

}  // namespace
}  // namespace fapc::xmt
