// The SMIL-Agent reader on small scripts: timing of containers, anchors and fill, what affects
// and actions draw, the warnings of what it does not know (span kept) and the errors, each at its
// place.
#include <gtest/gtest.h>

#include "fapc/smil/smil.hpp"
#include "fapc/speech/engine.hpp"

namespace fapc::smil {
namespace {

Result<SmilDocument> read(const std::string& text, SmilOptions options = {}) {
  return read_smil(text, "t.smil", options);
}

void expect_error(const std::string& text, int line, int column, const std::string& says, SmilOptions options = {}) {
  SCOPED_TRACE(text);
  const auto read_back = read(text, options);
  ASSERT_FALSE(read_back);
  EXPECT_EQ(read_back.error().where.file, "t.smil");
  EXPECT_EQ(read_back.error().where.line, line);
  EXPECT_EQ(read_back.error().where.column, column);
  EXPECT_NE(read_back.error().message.find(says), std::string::npos) << read_back.error().message;
}

bool has_warning(const SmilDocument& doc, const std::string& code) {
  for (const Diagnostic& w : doc.warnings)
    if (w.code == code) return true;
  return false;
}

TEST(SmilReader, ASeqPlacesActionsOneAfterTheOther) {
  const auto doc = read(R"(<seq>
  <action channel="alice-eyes" action-type="turning" intensity="0.5" dur="2s"><parameter>LookLeft</parameter></action>
  <action channel="alice-head" action-type="turning" dur="1s"><parameter>LookRight</parameter></action>
</seq>)");
  ASSERT_TRUE(doc) << format_diagnostic(doc.error());
  ASSERT_EQ(doc->behaviours.size(), 2u);
  EXPECT_EQ(doc->behaviours[0].name, "turning LookLeft");
  EXPECT_DOUBLE_EQ(doc->behaviours[0].start, 0);
  EXPECT_DOUBLE_EQ(doc->behaviours[0].end, 2);
  EXPECT_DOUBLE_EQ(doc->behaviours[1].start, 2);
  EXPECT_DOUBLE_EQ(doc->behaviours[1].end, 3);
  // The eyes turn left (positive eyeball yaw) by half the full turn; the head turns right.
  bool eyes = false;
  bool head = false;
  for (const Clip& clip : doc->timeline.clips) {
    if (clip.target == "yaw_l_eyeball") eyes = clip.curve.keys[1].value > 0 && clip.begin == 0;
    if (clip.target == "head_yaw") head = clip.curve.keys[1].value < 0 && clip.begin == 2;
  }
  EXPECT_TRUE(eyes);
  EXPECT_TRUE(head);
}

TEST(SmilReader, RepeatRunsAContainerAgain) {
  const auto doc = read(R"(<seq repeat="3"><action action-type="blink" channel="alice-eyes"/></seq>)");
  ASSERT_TRUE(doc) << format_diagnostic(doc.error());
  ASSERT_EQ(doc->behaviours.size(), 3u);
  EXPECT_NEAR(doc->behaviours[2].start, 0.6, 1e-9);  // a blink lasts 0.3 s
}

TEST(SmilReader, AffectsAnchoredToMarksSpanTheirWords) {
  const auto doc = read(R"(<par>
<speech id="s" affect="Sad"><mark id="a"/>One two three. <mark id="b"/>Four five six.<mark id="c"/></speech>
<speech-animation affect="SmileOpen" content-id="s" content-begin="a" content-end="b"/>
<speech-animation content-id="s" content-begin="b" fill="freeze"/>
</par>)");
  ASSERT_TRUE(doc) << format_diagnostic(doc.error());
  ASSERT_EQ(doc->behaviours.size(), 2u);
  EXPECT_EQ(doc->behaviours[0].name, "SmileOpen");
  EXPECT_EQ(doc->behaviours[1].name, "Sad");  // the speech's affect
  EXPECT_DOUBLE_EQ(doc->behaviours[0].start, 0);
  EXPECT_GT(doc->behaviours[0].end, 0.5);
  EXPECT_DOUBLE_EQ(doc->behaviours[1].start, doc->behaviours[0].end);
  // fill="freeze": the sad mouth holds after the speech.
  bool frozen = false;
  for (const Clip& clip : doc->timeline.clips)
    if (clip.target == "raise_l_cornerlip" && clip.fill == Fill::freeze) frozen = clip.curve.keys.back().value < 0;
  EXPECT_TRUE(frozen);
}

TEST(SmilReader, UnknownAffectsAndActionsWarnAndKeepTheirSpan) {
  const auto doc = read(R"(<par>
<speech-animation affect="Bored" dur="2s"/>
<action action-type="waving" dur="1s"/>
<action action-type="turning" dur="1s"><parameter>LookBehind</parameter></action>
</par>)");
  ASSERT_TRUE(doc) << format_diagnostic(doc.error());
  EXPECT_TRUE(has_warning(*doc, "smil.unknown_affect"));
  EXPECT_TRUE(has_warning(*doc, "smil.unknown_action"));
  ASSERT_EQ(doc->behaviours.size(), 3u);
  for (const PlacedBehaviour& b : doc->behaviours) EXPECT_FALSE(b.drawn);
  EXPECT_DOUBLE_EQ(doc->behaviours[0].end, 2);
  EXPECT_DOUBLE_EQ(doc->timeline.explicit_end.value_or(0), 2);
  for (const Diagnostic& w : doc->warnings)
    if (w.code == "smil.unknown_affect") {
      EXPECT_EQ(w.where.line, 2);
      EXPECT_EQ(w.where.column, 19);  // the affect attribute
    }
}

TEST(SmilReader, TextOutsideSpeechIsReportedNotDropped) {
  const auto doc = read("<seq>stray words<action action-type=\"blink\">more</action></seq>");
  ASSERT_TRUE(doc) << format_diagnostic(doc.error());
  EXPECT_GE(doc->warnings.size(), 2u);
  for (const Diagnostic& w : doc->warnings) EXPECT_EQ(w.where.line, 1);
}

TEST(SmilReader, PointingLooksAtThePoint) {
  const auto doc = read(R"(<par><action channel="alice-head" action-type="pointing" dur="1s">
<parameter>1</parameter><parameter>0</parameter><parameter>1</parameter></action></par>)");
  ASSERT_TRUE(doc) << format_diagnostic(doc.error());
  double yaw = 0;
  for (const Clip& clip : doc->timeline.clips)
    if (clip.target == "head_yaw") yaw = clip.curve.keys[1].value;
  EXPECT_NEAR(yaw, 45 * 1e5 * 3.14159265358979 / 180, 1);  // 45 degrees to the left
}

TEST(SmilReader, SystemLanguageChoosesTheVoice) {
  if (!speech::available()) GTEST_SKIP() << "built without the speech engine";
  SmilOptions options;
  options.speech.synthesize = speech::engine();
  const auto doc = read(R"(<seq><par system-language="italian"><speech>Buongiorno a tutti.</speech></par>
<speech system-language="en">Good morning.</speech></seq>)",
                        options);
  ASSERT_TRUE(doc) << format_diagnostic(doc.error());
  EXPECT_EQ(doc->languages, (std::vector<std::string>{"it", "en"}));
  ASSERT_EQ(doc->timeline.audio.size(), 2u);
  EXPECT_GT(doc->timeline.audio[1].begin, 0.5);  // after the first, in the seq
}

TEST(SmilReader, ErrorsArePlaced) {
  expect_error("<smil/>", 1, 1, "not a SMIL-Agent par or seq");
  expect_error("<par>\n  <speech-animation affect=\"Sad\" content-id=\"x\"/>\n</par>", 2, 34,
               "content-id 'x' names no speech");
  expect_error(
      "<par><speech id=\"s\">Hi <mark id=\"a\"/>there</speech>\n<action content-id=\"s\" content-begin=\"b\"/></par>",
      2, 24, "content-begin 'b' is no mark of speech 's'");
  expect_error("<par><action content-end=\"b\"/></par>", 1, 14, "needs content-id");
  expect_error(
      "<par><speech id=\"s\"><mark id=\"a\"/>Hi <mark id=\"b\"/>there</speech>\n"
      "<action content-id=\"s\" content-begin=\"b\" content-end=\"a\"/></par>",
      2, 1, "content-end comes before");
  expect_error("<seq><action dur=\"soon\"/></seq>", 1, 14, "dur 'soon' is not a time");
  expect_error("<seq><action fill=\"sometimes\"/></seq>", 1, 14, "fill 'sometimes'");
  expect_error("<seq><action intensity=\"2\"/></seq>", 1, 14, "intensity '2' is not a number from 0 to 1");
  expect_error("<seq repeat=\"-1\"/>", 1, 6, "repeat '-1'");
  expect_error("<seq>\n<speech id=\"s\"/></seq>", 2, 1, "speech has no text");
  expect_error("<seq><speech id=\"s\">a</speech>\n<speech id=\"s\">b</speech></seq>", 2, 9,
               "a second speech with id 's'");
  expect_error("<seq><speech>a <mark/> b</speech></seq>", 1, 16, "a mark needs an id");
  expect_error("<seq><speech file=\"../../etc/passwd\"/></seq>", 1, 14, "");
  expect_error("<seq><par>", 1, 11, "");  // not well formed
}

TEST(SmilReader, LimitsAreCheckedBeforeTheWork) {
  SmilOptions few;
  few.max_runs = 3;
  expect_error("<seq><seq/><seq/><seq/><seq/></seq>", 1, 18, "--max-runs", few);
  expect_error("<seq repeat=\"1000000000\"/>", 1, 6, "--max-runs");
  // Repeats of repeats are counted before the scheduler makes any run.
  expect_error("<seq repeat=\"100000\"><seq repeat=\"100000\"><action/></seq></seq>", 1, 1, "too many runs");
  SmilOptions short_text;
  short_text.speech_limits.max_speech_text_bytes = 10;
  expect_error("<seq><speech>short</speech>\n<speech>this is longer</speech></seq>", 2, 1, "bytes", short_text);
}

}  // namespace
}  // namespace fapc::smil
