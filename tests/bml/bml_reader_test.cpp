// The BML reader on small documents: timing read from attributes and constraints (OpenBMLParser's
// test cases, written again here), positioned errors naming the defect and the chain, the
// behaviours fapc does not draw reported once per kind, and what head and gaze lower to.
#include <gtest/gtest.h>

#include "fapc/bml/bml.hpp"

namespace fapc::bml {
namespace {

std::string block(const std::string& body) {
  return "<bml xmlns=\"http://www.bml-initiative.org/bml/bml-1.0\" id=\"bml1\" characterId=\"Alice\">\n" + body +
         "\n</bml>\n";
}

BmlDocument read_ok(const std::string& body) {
  Result<BmlDocument> d = read_bml(block(body), "t.bml");
  EXPECT_TRUE(d) << (d ? "" : format_diagnostic(d.error()));
  return d ? std::move(*d) : BmlDocument{};
}

Diagnostic read_error(const std::string& body) {
  Result<BmlDocument> d = read_bml(block(body), "t.bml");
  EXPECT_FALSE(d);
  return d ? Diagnostic{} : d.error();
}

const ScheduledBehaviour& behaviour(const BmlDocument& d, const std::string& id) {
  for (const ScheduledBehaviour& b : d.behaviours)
    if (b.id == id) return b;
  static const ScheduledBehaviour none;
  ADD_FAILURE() << "no behaviour " << id;
  return none;
}

TEST(BmlReader, BlockAndCharacterAreRead) {
  const BmlDocument d = read_ok("<head id=\"h1\" lexeme=\"NOD\"/>");
  EXPECT_EQ(d.dialect, "BML 1.0");
  EXPECT_EQ(d.blocks, std::vector<std::string>{"bml1"});
  EXPECT_EQ(d.characters, std::vector<std::string>{"Alice"});
}

TEST(BmlReader, OffsetChainWrittenBackwards) {
  const BmlDocument d = read_ok(R"(<head id="h1" lexeme="NOD" start="h2:start-2"/>
  <head id="h2" lexeme="NOD" start="h3:start-2"/>
  <head id="h3" lexeme="NOD" start="h4:start-2"/>
  <head id="h4" lexeme="NOD" start="10"/>)");
  EXPECT_DOUBLE_EQ(behaviour(d, "h1").start, 4);
  EXPECT_DOUBLE_EQ(behaviour(d, "h4").start, 10);
}

TEST(BmlReader, SynchronizeConstraintJoinsPoints) {
  const BmlDocument d = read_ok(R"(<head id="h1" lexeme="NOD" start="1"/>
  <faceLexeme id="f1" lexeme="RAISE_BROWS"/>
  <constraint><synchronize><sync ref="h1:end"/><sync ref="f1:start+0.5"/></synchronize></constraint>)");
  // h1 ends at 1 + 0.9 (one nod cycle with preparation and return); f1 starts 0.5 s before.
  EXPECT_NEAR(behaviour(d, "f1").start, 1 + 0.9 - 0.5, 1e-9);
}

TEST(BmlReader, ABehaviourThatLastsNoTimeIsSaidAndNotDrawn) {
  // Found by fuzzing: start and end on one mark made clips that end where they begin.
  const BmlDocument d = read_ok(R"(<faceLexeme id="f" lexeme="RAISE_BROWS" start="1" end="1"/>
<head id="h" lexeme="NOD" start="2" end="h:start"/>
<faceLexeme id="g" lexeme="RAISE_BROWS" start="1" end="2"/>)");
  for (const Clip& c : d.timeline.clips) EXPECT_LT(c.begin, c.end) << std::string(c.target);
  EXPECT_FALSE(d.timeline.clips.empty());  // g is drawn
  int said = 0;
  for (const Diagnostic& w : d.warnings) said += w.code == "bml.no_duration" ? 1 : 0;
  EXPECT_EQ(said, 2);
}

TEST(BmlReader, RepetitionIsAWholeNumberFromOneToAHundred) {
  // 2.7e120 once went through an int conversion first (undefined; found by fuzzing).
  for (const char* bad : {"26666666666666666666666666666666666666666666666666666666666666666666666666666666666666666666"
                          "66666666666666666666666666666",
                          "0", "1.5", "101"}) {
    const Diagnostic e = read_error(std::string(R"(<head id="n" lexeme="NOD" repetition=")") + bad + "\"/>");
    EXPECT_NE(e.message.find("repetition must be a whole number from 1 to 100"), std::string::npos)
        << bad << ": " << e.message;
  }
}

TEST(BmlReader, SelfReferenceSetsTheLength) {
  // testhead_selftimed.xml
  const BmlDocument d = read_ok(R"(<head id="shake1" start="0" end="shake1:start+1" lexeme="SHAKE"/>)");
  EXPECT_DOUBLE_EQ(behaviour(d, "shake1").end, 1);
}

TEST(BmlReader, AnEndBeforeTheStartIsAnErrorAtTheEnd) {
  const Diagnostic e = read_error(R"(<head id="nod1" lexeme="NOD" start="2" end="0"/>)");
  EXPECT_EQ(e.where.line, 2);
  EXPECT_EQ(e.where.column, 40);  // the end attribute
  EXPECT_NE(e.message.find("nod1:end"), std::string::npos) << e.message;
  EXPECT_NE(e.message.find("nod1 start=\"2\""), std::string::npos) << e.message;
}

TEST(BmlReader, AContradictoryCycleNamesItsChain) {
  const Diagnostic e = read_error(R"(<head id="a" lexeme="NOD" start="b:start+1"/>
<head id="b" lexeme="NOD" start="c:start+1"/>
<head id="c" lexeme="NOD" start="a:start"/>)");
  EXPECT_EQ(e.where.line, 4);
  EXPECT_NE(e.message.find("a start=\"b:start+1\" (line 2), then b start=\"c:start+1\" (line 3)"), std::string::npos)
      << e.message;
}

TEST(BmlReader, UnknownBehaviourAndSyncPointAreErrorsAtTheReference) {
  // testspeech_unknownbehavior.xml
  Diagnostic e = read_error(R"(<head id="h" lexeme="NOD" start="unknownbeh:end"/>)");
  EXPECT_EQ(e.where.line, 2);
  EXPECT_NE(e.message.find("no behaviour 'unknownbeh'"), std::string::npos) << e.message;
  e = read_error(R"(<head id="h" lexeme="NOD"/><head id="g" lexeme="NOD" start="h:climax"/>)");
  EXPECT_NE(e.message.find("no sync point 'climax'"), std::string::npos) << e.message;
}

TEST(BmlReader, AMalformedReferenceIsAnError) {
  // testinvalidxml2.xml's "nod1:relax:2" reads as block nod1, behaviour relax, point 2.
  const Diagnostic e = read_error(R"(<head id="h" lexeme="NOD" start="h:start+"/>)");
  EXPECT_NE(e.message.find("not a time nor a sync reference"), std::string::npos) << e.message;
}

TEST(BmlReader, BehavioursNotDrawnKeepTheirTimingAndAreReportedOncePerKind) {
  const BmlDocument d = read_ok(R"(<gesture id="g1" lexeme="BEAT" start="1"/>
<gesture id="g2" lexeme="BEAT" start="g1:end"/>
<pointing id="p1" target="x" start="0"/>
<head id="n1" lexeme="NOD" stroke="g2:stroke"/>)");
  int gesture = 0;
  int pointing = 0;
  for (const Diagnostic& w : d.warnings) {
    EXPECT_EQ(w.code, "bml.not_drawn");
    if (w.message.find("<gesture>") != std::string::npos) ++gesture;
    if (w.message.find("<pointing>") != std::string::npos) ++pointing;
  }
  EXPECT_EQ(gesture, 1);
  EXPECT_EQ(pointing, 1);
  EXPECT_FALSE(behaviour(d, "g2").drawn);
  EXPECT_DOUBLE_EQ(behaviour(d, "g2").start, 2.5);
  // n1's stroke (0.4 s after its start) at g2's stroke (0.6 s after 2.5).
  EXPECT_NEAR(behaviour(d, "n1").start, 2.5 + 0.6 - 0.4, 1e-9);
}

TEST(BmlReader, ANodPitchesTheHeadDownAndBackRepetitionTimes) {
  const BmlDocument d = read_ok(R"(<head id="n" lexeme="NOD" repetition="2" start="1"/>)");
  ASSERT_EQ(d.timeline.clips.size(), 1u);
  const Clip& c = d.timeline.clips[0];
  EXPECT_EQ(std::string(c.target), "head_pitch");
  int peaks = 0;
  for (const KeyPoint& k : c.curve.keys) peaks += k.value > 0 ? 1 : 0;
  EXPECT_EQ(peaks, 2);
  EXPECT_DOUBLE_EQ(c.begin, 1);
  EXPECT_DOUBLE_EQ(c.curve.value_at(0), 0);
  EXPECT_DOUBLE_EQ(c.curve.value_at(c.end - c.begin), 0);
}

TEST(BmlReader, AGazeOffsetTurnsTheEyesAndWithNeckInfluenceTheHead) {
  BmlDocument d = read_ok(R"(<gaze id="g" target="x" offsetAngle="20" offsetDirection="LEFT"/>)");
  ASSERT_EQ(d.timeline.clips.size(), 2u);  // both eyes' yaw
  EXPECT_EQ(std::string(d.timeline.clips[0].target), "yaw_l_eyeball");
  EXPECT_GT(d.timeline.clips[0].curve.value_at(1.0), 0);  // positive yaw: to the left
  bool warned = false;
  for (const Diagnostic& w : d.warnings) warned = warned || w.code == "bml.target_ahead";
  EXPECT_TRUE(warned);
  d = read_ok(R"(<gaze id="g" target="x" influence="NECK" offsetAngle="20" offsetDirection="DOWN"/>)");
  bool head = false;
  for (const Clip& c : d.timeline.clips) head = head || std::string(c.target) == "head_pitch";
  EXPECT_TRUE(head);
}

TEST(BmlReader, AnotherRootIsRefusedNamingIt) {
  Result<BmlDocument> d = read_bml("<fml-apml/>", "t.xml");
  ASSERT_FALSE(d);
  EXPECT_NE(d.error().message.find("<fml-apml>"), std::string::npos);
}

TEST(BmlReader, TooManyBehavioursIsALimitNamingTheOption) {
  ReaderOptions options;
  options.limits.max_runs = 2;
  Result<BmlDocument> d = read_bml(block("<wait id=\"a\"/><wait id=\"b\"/><wait id=\"c\"/>"), "t.bml", options);
  ASSERT_FALSE(d);
  EXPECT_EQ(d.error().kind, ErrorKind::limit_exceeded);
  EXPECT_NE(d.error().message.find("--max-runs"), std::string::npos);
}

// All of a document's speech counts against the speech limits, as FML's does: each speech alone is
// small, together they are over (docs/security.md).
TEST(BmlReader, AllSpeechTogetherIsBoundedByTheSpeechLimits) {
  const std::string two_speeches =
      "<speech id=\"s1\"><text>hello there, how are you</text></speech>\n"
      "<speech id=\"s2\" start=\"s1:end\"><text>fine, and you, my friend</text></speech>";
  ReaderOptions options;
  options.limits.max_speech_text_bytes = 40;
  Result<BmlDocument> d = read_bml(block(two_speeches), "t.bml", options);
  ASSERT_FALSE(d);
  EXPECT_EQ(d.error().code, "limit.speech_text");
  EXPECT_EQ(d.error().where.line, 3);  // the second speech, where the total passes the limit
  EXPECT_NE(d.error().message.find("--max-speech-text"), std::string::npos);

  options = ReaderOptions{};
  options.limits.max_speech_seconds = 2;  // each speech alone is shorter, the two together longer
  d = read_bml(block(two_speeches), "t.bml", options);
  ASSERT_FALSE(d);
  EXPECT_EQ(d.error().code, "limit.speech_seconds");
  EXPECT_EQ(d.error().where.line, 3);

  EXPECT_TRUE(read_bml(block(two_speeches), "t.bml", ReaderOptions{}));
}

TEST(BmlReader, DuplicateIdsAreAnError) {
  const Diagnostic e = read_error("<wait id=\"a\"/>\n<wait id=\"a\"/>");
  EXPECT_EQ(e.where.line, 3);
}

}  // namespace
}  // namespace fapc::bml
