// FML timing (docs/fml.md, "Timing") against spans worked out by hand: in a seq, begin and
// end count from the previous element's end; in a par from the par's start; end wins over
// duration; moves last 1 s by default; actions run one after another; repeat by count, by event
// and indefinitely; excl branches chosen by event values; templates played by behavior.
#include "fml_test_helpers.hpp"

namespace fapc::xmt {
namespace {

using namespace fml_test;

std::string jaw(const std::string& timing, int value = 100) {
  return "<fap type=\"open_jaw\" val=\"" + std::to_string(value) + "\" " + timing + "/>";
}

TEST(FmlTiming, BeginInASeqCountsFromThePreviousEnd) {
  // The second move starts 0.5 s after the first ends: [1.5, 2.5).
  const auto doc =
      read_ok(in_action("<seq>" + jaw("duration=\"1s\"") + jaw("begin=\"0.5s\" duration=\"1s\"") + "</seq>"));
  EXPECT_EQ(spans(doc.timeline), (Spans{{"open_jaw", 0, 1}, {"open_jaw", 1.5, 2.5}}));
  EXPECT_EQ(doc.timeline.explicit_end, 2.5);
}

TEST(FmlTiming, BeginInAParCountsFromTheParStart) {
  const auto doc =
      read_ok(in_action("<par begin=\"1s\">" + jaw("begin=\"0.5s\" duration=\"2s\"") + jaw("dur=\"1s\"") + "</par>"));
  EXPECT_EQ(spans(doc.timeline), (Spans{{"open_jaw", 1, 2}, {"open_jaw", 1.5, 3.5}}));
}

TEST(FmlTiming, EndWinsOverDurationAndCountsLikeBegin) {
  // In the seq the second move's begin (0.5) and end (2) both count from 1: [1.5, 3), not 5 s.
  const auto doc = read_ok(
      in_action("<seq>" + jaw("duration=\"1s\"") + jaw("begin=\"0.5s\" end=\"2s\" duration=\"5s\"") + "</seq>"));
  EXPECT_EQ(spans(doc.timeline), (Spans{{"open_jaw", 0, 1}, {"open_jaw", 1.5, 3}}));
}

TEST(FmlTiming, MovesLastOneSecondByDefaultAndTimesTakeUnits) {
  const auto doc =
      read_ok(in_action(jaw("") + jaw("duration=\"250ms\"") + jaw("duration=\"2\"") + jaw("duration=\"0.01min\"")));
  EXPECT_EQ(spans(doc.timeline),
            (Spans{{"open_jaw", 0, 1}, {"open_jaw", 1, 1.25}, {"open_jaw", 1.25, 3.25}, {"open_jaw", 3.25, 3.85}}));
}

TEST(FmlTiming, ActionsRunOneAfterAnother) {
  const auto doc = read_ok(document("<story><action>" + jaw("duration=\"2s\"") + "</action><act>" +
                                    jaw("duration=\"1s\"") + "</act></story>"));
  EXPECT_EQ(spans(doc.timeline), (Spans{{"open_jaw", 0, 2}, {"open_jaw", 2, 3}}));
}

TEST(FmlTiming, RepeatCountRepeatsAContainer) {
  const auto doc =
      read_ok(in_action("<seq repeat=\"2\">" + jaw("duration=\"1s\"") + jaw("duration=\"0.5s\"", 0) + "</seq>"));
  EXPECT_EQ(spans(doc.timeline),
            (Spans{{"open_jaw", 0, 1}, {"open_jaw", 1, 1.5}, {"open_jaw", 1.5, 2.5}, {"open_jaw", 2.5, 3}}));
}

TEST(FmlTiming, RepeatByAnEventTakesItsValueAsTheCount) {
  const std::string model = "<event name=\"quit\" val=\"3\"/>";
  const std::string text = in_action("<seq repeat=\"quit\">" + jaw("duration=\"1s\"") + "</seq>", model);
  EXPECT_EQ(read_ok(text).timeline.clips.size(), 3u);
  FmlOptions zero;
  zero.events = {{"quit", "0"}};  // set to 0: it stops after the run in progress
  EXPECT_EQ(read_ok(text, zero).timeline.clips.size(), 1u);
}

TEST(FmlTiming, AnUnsetLoopEventRepeatsUntilTheDuration) {
  const std::string text =
      in_action("<seq repeat=\"quit\">" + jaw("duration=\"1s\"") + "</seq>", "<event name=\"quit\" val=\"-1\"/>");
  EXPECT_EQ(read_error(text),
            "t.fml:3:16: error: seq repeats indefinitely and nothing around it ends: give it or a parent an end "
            "(repeat=\"indefinite\" and unset loop events need an end: a container's duration or end, or --duration)");
  FmlOptions options;
  options.duration = 2.5;
  EXPECT_EQ(spans(read_ok(text, options).timeline),
            (Spans{{"open_jaw", 0, 1}, {"open_jaw", 1, 2}, {"open_jaw", 2, 2.5}}));
}

TEST(FmlTiming, RepeatUntilAnEventHasAValue) {
  // "kbd;F3": loop until kbd is F3. Already F3: once; anything else: until the container's end.
  const std::string text =
      in_action("<par duration=\"3s\"><seq repeat=\"kbd;F3\">" + jaw("duration=\"1s\"") + "</seq></par>",
                "<event name=\"kbd\"/>");
  FmlOptions pressed;
  pressed.events = {{"kbd", "F3"}};
  EXPECT_EQ(read_ok(text, pressed).timeline.clips.size(), 1u);
  EXPECT_EQ(read_ok(text).timeline.clips.size(), 3u);
}

TEST(FmlTiming, ExclPlaysTheBranchOfTheEventsValue) {
  const std::string model = "<event name=\"user\" val=\"0\"/>";
  const std::string text =
      in_action("<excl ev_name=\"user\">" + jaw("ev_val=\"0\"", 10) + jaw("ev_val=\"1\"", 20) + "</excl>", model);
  // The model's val chooses, --event overrides it.
  ASSERT_EQ(read_ok(text).timeline.clips.size(), 1u);
  EXPECT_EQ(read_ok(text).timeline.clips[0].curve.keys.back().value, 10);
  FmlOptions one;
  one.events = {{"user", "1"}};
  EXPECT_EQ(read_ok(text, one).timeline.clips[0].curve.keys.back().value, 20);
  FmlOptions none;
  none.events = {{"user", "7"}};
  const auto unmatched = read_ok(text, none);
  EXPECT_TRUE(unmatched.timeline.clips.empty());
  EXPECT_EQ(messages(unmatched.warnings),
            (std::vector<std::string>{
                "t.fml:3:16: warning: no branch of the excl has ev_val=\"7\" (event 'user'): it plays nothing"}));
}

TEST(FmlTiming, BehaviorPlaysItsTemplateInPlace) {
  // FML Figure 5: "Hello" (3 visemes at 12/s = 0.25 s, then 30 ms of fade to neutral: 0.28 s),
  // then the head turns by 3 s later.
  const std::string model =
      "<range type=\"left\" val=\"60\"/><template name=\"hi\"><seq begin=\"0\"><talk>Hello</talk>"
      "<hdmv type=\"0\" begin=\"0\" end=\"3s\" val=\"30\"/></seq></template>";
  const auto doc = read_ok(document("<story><behavior name=\"hi\"/></story>", model));
  ASSERT_EQ(doc.timeline.clips.size(), 4u);
  EXPECT_EQ(std::get<0>(spans(doc.timeline)[3]), "head_yaw");
  EXPECT_DOUBLE_EQ(doc.timeline.clips[3].begin, 0.28);
  EXPECT_DOUBLE_EQ(doc.timeline.clips[3].end, 3.28);
  EXPECT_EQ(doc.templates, (std::vector<std::string>{"hi"}));
}

TEST(FmlTiming, UnknownElementsKeepTheirChildrenAndTimingWithAWarning) {
  const auto doc = read_ok(document("<story>\n<emotion begin=\"1s\">" + jaw("duration=\"2s\"") + "</emotion></story>"));
  EXPECT_EQ(spans(doc.timeline), (Spans{{"open_jaw", 1, 3}}));
  EXPECT_EQ(
      messages(doc.warnings),
      (std::vector<std::string>{"t.fml:4:1: warning: element 'emotion' is not part of FML; its children are read as "
                                "if in a par"}));
}

TEST(FmlTiming, VariantSpellingsAreReadWithANoteOnce) {
  const std::string model = "<event id=\"answer\" val=\"1\"/>";
  const auto doc =
      read_ok(in_action("<excl ev_id=\"answer\"><fap type=\"3\" value=\"5\" event_value=\"1\"/>"
                        "<fap type=\"3\" value=\"6\" event_value=\"2\"/></excl>",
                        model));
  ASSERT_EQ(doc.timeline.clips.size(), 1u);
  EXPECT_EQ(doc.timeline.clips[0].curve.keys.back().value, 5);
  EXPECT_EQ(messages(doc.warnings),
            (std::vector<std::string>{
                "t.fml:2:15: warning: id is read as name, the paper's spelling",
                "t.fml:3:22: warning: ev_id is read as ev_name, the paper's spelling",
                "t.fml:3:61: warning: event_value is read as ev_val, the paper's spelling (2 times; first here)",
                "t.fml:3:51: warning: value is read as val, the paper's spelling (2 times; first here)",
            }));
}

TEST(FmlTiming, UnknownAttributesAreReportedOncePerElementAndName) {
  const auto doc = read_ok(in_action(jaw("speed=\"2\"") + jaw("speed=\"3\"")));
  EXPECT_EQ(
      messages(doc.warnings),
      (std::vector<std::string>{"t.fml:3:47: warning: attribute 'speed' of fap is not part of FML and was ignored "
                                "(2 times; first here)"}));
}

}  // namespace
}  // namespace fapc::xmt
