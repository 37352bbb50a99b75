// SMIL timing of XMT-Omega documents: clock values and the intervals of par, seq and excl with
// begin, dur, end, repeatCount, repeatDur and fill. Every expected interval was worked out by hand
// from the SMIL 2.0 rules (docs/xmt-omega.md, "Timing"); times are binary fractions so that the
// comparisons are exact.
#include <gtest/gtest.h>

#include "xmto_test_helpers.hpp"

namespace fapc::xmt {
namespace {

using test::document;
using test::read_error;
using test::read_ok;
using test::spans;
using test::Spans;

// An animate of open_jaw with the given timing attributes (from 0 to 100).
std::string jaw(const std::string& timing) {
  return "<animate attributeName=\"open_jaw\" from=\"0\" to=\"100\" " + timing + "/>";
}

TEST(XmtoClock, ValuesOfEveryForm) {
  EXPECT_EQ(parse_clock_value("3"), 3);
  EXPECT_EQ(parse_clock_value("3s"), 3);
  EXPECT_EQ(parse_clock_value("2.5s"), 2.5);
  EXPECT_EQ(parse_clock_value("250ms"), 0.25);
  EXPECT_EQ(parse_clock_value("1.5min"), 90);
  EXPECT_EQ(parse_clock_value("2h"), 7200);
  EXPECT_EQ(parse_clock_value("00:00:03.5"), 3.5);
  EXPECT_EQ(parse_clock_value("1:02:03"), 3723);  // hours need not have two digits
  EXPECT_EQ(parse_clock_value("01:30"), 90);      // partial clock: minutes and seconds
  EXPECT_EQ(parse_clock_value("02:30.25"), 150.25);
  EXPECT_EQ(parse_clock_value(" 4s "), 4);  // SMIL allows surrounding white space
}

TEST(XmtoClock, RejectsWhatSmilDoesNotAllow) {
  for (const char* bad : {"", "s", "3x", ".5s", "5.", "3 s", "1:60", "00:1:00", "1:00:60", "-3s", "+3s", "1e3", "inf",
                          "nan", "3ss", "1.5:00", "indefinite", "1:2:3:4"}) {
    EXPECT_FALSE(parse_clock_value(bad).has_value()) << bad;
  }
}

TEST(XmtoTiming, BodyIsASequence) {
  const auto doc = read_ok(document(jaw("dur=\"2s\"") + jaw("dur=\"3s\"")));
  EXPECT_EQ(spans(doc.timeline), (Spans{{"open_jaw", 0, 2}, {"open_jaw", 2, 5}}));
  EXPECT_EQ(doc.timeline.explicit_end, 5);
}

TEST(XmtoTiming, BeginInASeqCountsFromThePreviousEnd) {
  // b starts 0.5 s after a ends: [1.5, 2.5).
  const auto doc = read_ok(document("<seq>" + jaw("dur=\"1s\"") + jaw("dur=\"1s\" begin=\"0.5s\"") + "</seq>"));
  EXPECT_EQ(spans(doc.timeline), (Spans{{"open_jaw", 0, 1}, {"open_jaw", 1.5, 2.5}}));
}

TEST(XmtoTiming, BeginInAParCountsFromTheParStart) {
  const auto doc =
      read_ok(document("<par begin=\"1s\">" + jaw("dur=\"2s\" begin=\"0.5s\"") + jaw("dur=\"1s\"") + "</par>"));
  EXPECT_EQ(spans(doc.timeline), (Spans{{"open_jaw", 1.5, 3.5}, {"open_jaw", 1, 2}}));
  EXPECT_EQ(doc.timeline.explicit_end, 3.5);
}

TEST(XmtoTiming, EndAloneSetsTheActiveDuration) {
  // No dur: the simple duration is indefinite; active from 1 to 3.
  const auto doc = read_ok(document("<par>" + jaw("begin=\"1s\" end=\"3s\"") + "</par>"));
  EXPECT_EQ(spans(doc.timeline), (Spans{{"open_jaw", 1, 3}}));
}

TEST(XmtoTiming, EndOnlyShortensDur) {
  // SMIL: active duration = min(dur, end - begin). dur 2, end 5: [0, 2), no repeat.
  // dur 4, begin 1, end 3: min(4, 2) = 2: [1, 3).
  const auto doc =
      read_ok(document("<par>" + jaw("dur=\"2s\" end=\"5s\"") + jaw("dur=\"4s\" begin=\"1s\" end=\"3s\"") + "</par>"));
  EXPECT_EQ(spans(doc.timeline), (Spans{{"open_jaw", 0, 2}, {"open_jaw", 1, 3}}));
}

TEST(XmtoTiming, FractionalRepeatCountCutsTheLastRun) {
  const auto doc = read_ok(document(jaw("dur=\"2s\" repeatCount=\"2.5\"")));
  EXPECT_EQ(spans(doc.timeline), (Spans{{"open_jaw", 0, 2}, {"open_jaw", 2, 4}, {"open_jaw", 4, 5}}));
}

TEST(XmtoTiming, RepeatDurAloneRepeatsUntilIt) {
  const auto doc = read_ok(document(jaw("dur=\"2s\" repeatDur=\"5s\"")));
  EXPECT_EQ(spans(doc.timeline), (Spans{{"open_jaw", 0, 2}, {"open_jaw", 2, 4}, {"open_jaw", 4, 5}}));
}

TEST(XmtoTiming, RepeatCountAndRepeatDurTakeTheShorter) {
  // 3 x 2 s = 6 s against 5 s: 5 s. 2 x 2 s = 4 s against 5 s: 4 s.
  const auto doc = read_ok(document("<par>" + jaw("dur=\"2s\" repeatCount=\"3\" repeatDur=\"5s\"") +
                                    jaw("dur=\"2s\" repeatCount=\"2\" repeatDur=\"5s\"") + "</par>"));
  EXPECT_EQ(
      spans(doc.timeline),
      (Spans{{"open_jaw", 0, 2}, {"open_jaw", 2, 4}, {"open_jaw", 4, 5}, {"open_jaw", 0, 2}, {"open_jaw", 2, 4}}));
}

TEST(XmtoTiming, EndCapsAnIndefiniteRepeat) {
  const auto doc =
      read_ok(document("<par>" + jaw("dur=\"1s\" begin=\"0.5s\" end=\"2.75s\" repeatCount=\"indefinite\"") + "</par>"));
  EXPECT_EQ(spans(doc.timeline), (Spans{{"open_jaw", 0.5, 1.5}, {"open_jaw", 1.5, 2.5}, {"open_jaw", 2.5, 2.75}}));
}

TEST(XmtoTiming, IndefiniteRepeatEndsWithTheParDur) {
  const auto doc = read_ok(document("<par dur=\"2.5s\">" + jaw("dur=\"1s\" repeatCount=\"indefinite\"") + "</par>"));
  EXPECT_EQ(spans(doc.timeline), (Spans{{"open_jaw", 0, 1}, {"open_jaw", 1, 2}, {"open_jaw", 2, 2.5}}));
}

TEST(XmtoTiming, IndefiniteRepeatAtTheTopNeedsADuration) {
  const std::string text = document(jaw("dur=\"1s\" repeatCount=\"indefinite\""));
  EXPECT_EQ(read_error(text),
            "t.xmt:3:1: error: animate has no duration and nothing around it ends: give it a "
            "duration, or place it in a parallel with a known end (repeatCount=\"indefinite\" needs "
            "an end: from a par with dur, end, repeatDur or --duration)");
  XmtoOptions options;
  options.duration = 2.5;  // --duration
  const auto doc = read_ok(text, options);
  EXPECT_EQ(spans(doc.timeline), (Spans{{"open_jaw", 0, 1}, {"open_jaw", 1, 2}, {"open_jaw", 2, 2.5}}));
  EXPECT_EQ(doc.timeline.explicit_end, 2.5);
}

TEST(XmtoTiming, OpenEndedAnimateStretchesToTheParEnd) {
  // No dur and no end: indefinite; in a par it lasts to the par's end (3 s, from its sibling).
  const auto doc = read_ok(document("<par>" + jaw("") + jaw("dur=\"3s\"") + "</par>"));
  EXPECT_EQ(spans(doc.timeline), (Spans{{"open_jaw", 0, 3}, {"open_jaw", 0, 3}}));
}

TEST(XmtoTiming, GroupDurCutsItsChildren) {
  const auto doc =
      read_ok(document("<par dur=\"1.5s\">" + jaw("dur=\"2s\"") + jaw("dur=\"1s\" begin=\"2s\"") + "</par>"));
  // The second child would begin after the par has ended: it never plays.
  EXPECT_EQ(spans(doc.timeline), (Spans{{"open_jaw", 0, 1.5}}));
}

TEST(XmtoTiming, GroupEndAloneDoesNotRepeatIt) {
  // The par's children last 1 s; end 3 s keeps it active (its child frozen) but repeats nothing.
  const auto doc =
      read_ok(document("<par end=\"3s\" fill=\"freeze\">" + jaw("dur=\"1s\"") + "</par>" + jaw("dur=\"1s\"")));
  EXPECT_EQ(spans(doc.timeline), (Spans{{"open_jaw", 0, 1}, {"open_jaw", 3, 4}}));
}

TEST(XmtoTiming, RepeatedSeqRepeatsItsChildren) {
  // The seq lasts 1 + 0.25 + 1 = 2.25 s; the second run starts at 2.25.
  const auto doc =
      read_ok(document("<seq repeatCount=\"2\">" + jaw("dur=\"1s\"") + jaw("dur=\"1s\" begin=\"0.25s\"") + "</seq>"));
  EXPECT_EQ(spans(doc.timeline),
            (Spans{{"open_jaw", 0, 1}, {"open_jaw", 2.25, 3.25}, {"open_jaw", 1.25, 2.25}, {"open_jaw", 3.5, 4.5}}));
}

TEST(XmtoTiming, ExclLetsTheLaterChildCutTheEarlier) {
  const auto doc =
      read_ok(document("<excl>" + jaw("dur=\"3s\" begin=\"0s\"") + jaw("dur=\"3s\" begin=\"1s\"") + "</excl>"));
  EXPECT_EQ(spans(doc.timeline), (Spans{{"open_jaw", 0, 1}, {"open_jaw", 1, 4}}));
}

TEST(XmtoTiming, ExclChildWithoutBeginNeverPlays) {
  const auto doc = read_ok(document("<excl>" + jaw("dur=\"3s\"") + jaw("dur=\"1s\" begin=\"1s\"") + "</excl>"));
  EXPECT_EQ(spans(doc.timeline), (Spans{{"open_jaw", 1, 2}}));
  EXPECT_EQ(test::messages(doc.warnings),
            std::vector<std::string>{"t.xmt:3:7: warning: animate in excl never plays: without begin it "
                                     "waits for an event (SMIL); give it a begin"});
}

TEST(XmtoTiming, IndefiniteBeginAndEndBeforeBeginNeverPlay) {
  const auto doc = read_ok(document("<par>" + jaw("dur=\"1s\" begin=\"indefinite\"") + jaw("begin=\"2s\" end=\"1s\"") +
                                    jaw("dur=\"1s\"") + "</par>"));
  EXPECT_EQ(spans(doc.timeline), (Spans{{"open_jaw", 0, 1}}));
  EXPECT_EQ(doc.warnings.size(), 2u);
}

TEST(XmtoTiming, NegativeBeginThatStartsBeforeZeroIsAnError) {
  EXPECT_EQ(read_error(document("<par>" + jaw("dur=\"1s\" begin=\"-1s\"") + "</par>")),
            "t.xmt:3:6: error: animate starts before time 0 (at -1 s)");
}

TEST(XmtoTiming, NegativeBeginInsideALaterParIsFine) {
  const auto doc = read_ok(document("<par begin=\"2s\">" + jaw("dur=\"1s\" begin=\"-1.5s\"") + "</par>"));
  EXPECT_EQ(spans(doc.timeline), (Spans{{"open_jaw", 0.5, 1.5}}));
}

TEST(XmtoTiming, FillFreezeIsInheritedFromTheContainer) {
  const auto doc =
      read_ok(document("<par fill=\"freeze\">" + jaw("dur=\"1s\"") + jaw("dur=\"1s\" fill=\"remove\"") + "</par>"));
  ASSERT_EQ(doc.timeline.clips.size(), 2u);
  EXPECT_EQ(doc.timeline.clips[0].fill, Fill::freeze);
  EXPECT_EQ(doc.timeline.clips[1].fill, Fill::remove);
}

TEST(XmtoTiming, FillAutoFreezesOnlyUntimedElements) {
  // SMIL's fill="auto": freeze when none of dur, end, repeatCount, repeatDur is given.
  const auto doc = read_ok(document("<par dur=\"2s\">" + jaw("fill=\"auto\"") + jaw("dur=\"1s\" fill=\"auto\"") +
                                    jaw("dur=\"1s\" fill=\"hold\"") + "</par>"));
  ASSERT_EQ(doc.timeline.clips.size(), 3u);
  EXPECT_EQ(doc.timeline.clips[0].fill, Fill::freeze);
  EXPECT_EQ(doc.timeline.clips[1].fill, Fill::remove);
  EXPECT_EQ(doc.timeline.clips[2].fill, Fill::freeze);  // hold is read as freeze
}

TEST(XmtoTiming, ClockFormsInAttributes) {
  const auto doc = read_ok(document("<par>" + jaw("begin=\"00:00:01.5\" dur=\"500ms\"") +
                                    jaw("begin=\"00:01\" dur=\"0.25min\"") + "</par>"));
  EXPECT_EQ(spans(doc.timeline), (Spans{{"open_jaw", 1.5, 2}, {"open_jaw", 1, 16}}));
}

TEST(XmtoTiming, RefusesToScheduleMillionsOfRuns) {
  // 1e9 runs of 1 ms; 5000 runs of a group of 1000 runs each (5 s, 1 ms animations).
  EXPECT_EQ(read_error(document(jaw("dur=\"1ms\" repeatCount=\"1e9\""))),
            "t.xmt:3:1: error: animate brings the document to too many clips (repeats of repeats?): "
            "more than the limit of 4000000 runs (--max-runs N raises it)");
  EXPECT_EQ(read_error(document("<par dur=\"5000s\"><seq dur=\"1s\" repeatCount=\"indefinite\">" +
                                jaw("dur=\"1ms\" repeatCount=\"1000\"") + "</seq></par>")),
            "t.xmt:3:57: error: animate brings the document to too many clips (repeats of repeats?): "
            "more than the limit of 4000000 runs (--max-runs N raises it)");
  // Repeats of repeats below the limit are fine: 100 x 100 runs.
  EXPECT_EQ(read_ok(document("<seq repeatCount=\"100\">" + jaw("dur=\"1ms\" repeatCount=\"100\"") + "</seq>"))
                .timeline.clips.size(),
            10000u);
}

}  // namespace
}  // namespace fapc::xmt
