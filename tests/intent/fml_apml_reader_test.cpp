// The FML-APML reader (docs/intentions.md), without a speech engine so that marks fall in
// proportion to the text (the BML reader's rule, compared here with a BML document of the same
// speech): spans from marks, times and other intentions; importance; the errors and warnings.
#include <gtest/gtest.h>

#include <algorithm>

#include "fapc/intent/intent.hpp"

namespace fapc::intent {
namespace {

constexpr const char* kSpeech =
    R"(<speech id="s1"><tm id="tm1"/>Hello there. <tm id="tm2"/>How are you today?<tm id="tm3"/></speech>)";

Result<IntentDocument> read(const std::string& fml, const IntentOptions& options = {}) {
  return read_fml_apml("<fml-apml>\n<bml>" + std::string(kSpeech) + "</bml>\n<fml>\n" + fml + "</fml>\n</fml-apml>\n",
                       "t.xml", options);
}

double mark_time(const std::string& id) {
  const auto bml = bml::read_bml("<bml id=\"b\">" + std::string(kSpeech) + "</bml>", "t.bml");
  EXPECT_TRUE(bml);
  for (const bml::ScheduledMark& m : bml->marks)
    if (m.id == id) return m.time;
  ADD_FAILURE() << "no mark " << id;
  return -1;
}

double peak_of(const Timeline& t, const std::string& target) {
  double peak = 0;
  for (const Clip& c : t.clips)
    if (c.target == target)
      for (const KeyPoint& k : c.curve.keys) peak = std::max(peak, std::abs(k.value));
  return peak;
}

bool has_warning(const Diagnostics& warnings, const std::string& code, int line) {
  return std::any_of(warnings.begin(), warnings.end(),
                     [&](const Diagnostic& w) { return w.code == code && w.where.line == line && w.where.column > 0; });
}

TEST(FmlApmlReader, AnIntentionSpansTheMarksItNames) {
  const auto d = read(R"(<emotion id="e1" type="joy" start="s1:tm2" end="s1:tm3"/>)");
  ASSERT_TRUE(d) << d.error().message;
  ASSERT_EQ(d->intentions.size(), 1u);
  EXPECT_NEAR(d->intentions[0].start, mark_time("tm2"), 1e-9);
  EXPECT_NEAR(d->intentions[0].end, mark_time("tm3"), 1e-9);
  EXPECT_GT(mark_time("tm2"), 0.1);
  EXPECT_EQ(d->intentions[0].behaviours, 2);  // joy: AU 6 and AU 12
  EXPECT_GT(peak_of(d->timeline, "raise_l_cornerlip"), 0);
}

TEST(FmlApmlReader, TimesOffsetsAndOtherIntentionsPlaceASpan) {
  const auto d = read(R"(<emotion id="e1" type="joy" start="0.5" end="s1:tm2+0.25"/>
<performative id="p1" type="inform" start="e1:end" end="e1:end+1"/>)");
  ASSERT_TRUE(d) << d.error().message;
  EXPECT_NEAR(d->intentions[0].start, 0.5, 1e-9);
  EXPECT_NEAR(d->intentions[0].end, mark_time("tm2") + 0.25, 1e-9);
  EXPECT_NEAR(d->intentions[1].start, d->intentions[0].end, 1e-9);
  EXPECT_NEAR(d->intentions[1].end, d->intentions[0].end + 1, 1e-9);
}

TEST(FmlApmlReader, ImportanceScalesTheBehaviours) {
  const auto full = read(R"(<emotion id="e1" type="joy" start="0" end="2" importance="1"/>)");
  const auto half = read(R"(<emotion id="e1" type="joy" start="0" end="2" importance="0.5"/>)");
  ASSERT_TRUE(full && half);
  EXPECT_GT(peak_of(full->timeline, "raise_l_cornerlip"), 0);
  EXPECT_NEAR(peak_of(half->timeline, "raise_l_cornerlip"), peak_of(full->timeline, "raise_l_cornerlip") / 2, 1e-9);
}

TEST(FmlApmlReader, AnIntentionDrawsWhatTheSameBmlBehaviourDraws) {
  vocabulary::BehaviourLexicon lexicon{"one.tsv", {}};
  vocabulary::LexiconRow row;
  row.intention = "emphasis";
  row.value = "*";
  row.behaviour = vocabulary::LexiconBehaviour::lexeme;
  row.name = "RAISE_BROWS";
  row.amount = 0.6;
  row.start = 0;
  row.ready = 0.2;
  row.relax = 0.8;
  row.end = 1;
  row.reason = "test";
  lexicon.rows.push_back(row);
  IntentOptions options;
  options.lexicon = &lexicon;
  const auto d = read(R"(<emphasis id="x" start="1" end="3"/>)", options);
  ASSERT_TRUE(d) << d.error().message;
  const auto b = bml::read_bml(
      R"(<bml id="b"><faceLexeme id="f" lexeme="RAISE_BROWS" amount="0.6" start="1" ready="1.4" relax="2.6" end="3"/></bml>)",
      "t.bml");
  ASSERT_TRUE(b) << b.error().message;
  std::vector<const Clip*> mine;
  for (const Clip& c : d->timeline.clips)
    if (c.source.line == 4) mine.push_back(&c);  // the emphasis's, not the speech's
  ASSERT_EQ(mine.size(), b->timeline.clips.size());
  for (std::size_t i = 0; i < mine.size(); ++i) {
    const Clip& theirs = b->timeline.clips[i];
    EXPECT_EQ(mine[i]->target, theirs.target);
    EXPECT_NEAR(mine[i]->begin, theirs.begin, 1e-9);
    EXPECT_NEAR(mine[i]->end, theirs.end, 1e-9);
    ASSERT_EQ(mine[i]->curve.keys.size(), theirs.curve.keys.size());
    for (std::size_t k = 0; k < theirs.curve.keys.size(); ++k) {
      EXPECT_NEAR(mine[i]->curve.keys[k].time, theirs.curve.keys[k].time, 1e-9);
      EXPECT_NEAR(mine[i]->curve.keys[k].value, theirs.curve.keys[k].value, 1e-9);
    }
  }
}

TEST(FmlApmlReader, AnUnknownIntentionIsAWarningAndKeepsItsSpan) {
  const auto d = read(R"(<emotion id="e1" type="melancholy" start="0" end="9"/>
<flourish id="f1" start="1" end="2"/>)");
  ASSERT_TRUE(d) << d.error().message;
  EXPECT_TRUE(has_warning(d->warnings, "intent.unknown_intention", 4));
  EXPECT_TRUE(has_warning(d->warnings, "intent.unknown_intention", 5));
  ASSERT_EQ(d->intentions.size(), 2u);
  EXPECT_EQ(d->intentions[0].behaviours, 0);
  EXPECT_GE(d->timeline.explicit_end.value_or(0), 9.0);
}

TEST(FmlApmlReader, GretaZeroEndsEarlierThanPlainStartsAreDurations) {
  const auto d = read(R"(<world id="w" start="3.2" end="0.5"/>)");
  ASSERT_TRUE(d) << d.error().message;
  EXPECT_NEAR(d->intentions[0].end, 3.7, 1e-9);
  EXPECT_TRUE(has_warning(d->warnings, "intent.time_from_start", 4));
}

TEST(FmlApmlReader, AnIntentionWithoutEndIsAPoint) {
  const auto d = read(R"(<backchannel id="b" type="agreement" start="1"/>)");
  ASSERT_TRUE(d) << d.error().message;
  EXPECT_NEAR(d->intentions[0].end - d->intentions[0].start, kPointSpanSeconds, 1e-9);
}

struct Bad {
  const char* fml;
  int line;
  int column;
  const char* says;
};

TEST(FmlApmlReader, BadSpansAreRefusedWhereTheyAreWritten) {
  const Bad cases[] = {
      {R"(<emotion id="e" type="joy" start="s1:tm9" end="s1:tm3"/>)", 4, 28, "its marks are tm1, tm2, tm3"},
      {R"(<emotion id="e" type="joy" start="nobody:start"/>)", 4, 28, "no speech, behaviour or intention 'nobody'"},
      {R"(<emotion id="e" type="joy" start="s1:tm3" end="s1:tm1"/>)", 4, 43, "is before start"},
      {R"(<emotion id="e" type="joy" start="0" importance="2"/>)", 4, 38, "from 0 to 1"},
      {R"(<emotion id="e" type="joy" start="s1:"/>)", 4, 28, ""},
      {R"(<emotion id="e" type="joy" end="1"/>)", 4, 1, "needs start"},
      {R"(<emotion id="e" type="joy" start="-1"/>)", 4, 28, "before the document's start"},
      {"<a id=\"a\" start=\"b:start\"/>\n<b id=\"b\" start=\"a:end\"/>", 5, 11, "cycle"},
  };
  for (const Bad& c : cases) {
    SCOPED_TRACE(c.fml);
    const auto d = read(c.fml);
    ASSERT_FALSE(d);
    EXPECT_EQ(d.error().where.file, "t.xml");
    EXPECT_EQ(d.error().where.line, c.line);
    EXPECT_EQ(d.error().where.column, c.column);
    EXPECT_NE(d.error().message.find(c.says), std::string::npos) << d.error().message;
  }
}

TEST(FmlApmlReader, MoreIntentionsThanTheLimitAreRefusedAtTheFirstTooMany) {
  IntentOptions options;
  options.bml.max_behaviours = 3;
  std::string fml;
  for (int i = 0; i < 4; ++i) fml += "<beat id=\"b" + std::to_string(i) + "\" start=\"0\"/>\n";
  const auto d = read(fml, options);
  ASSERT_FALSE(d);
  EXPECT_EQ(d.error().kind, ErrorKind::limit_exceeded);
  EXPECT_EQ(d.error().where.line, 7);
  EXPECT_NE(d.error().message.find("--max-runs"), std::string::npos);
}

TEST(FmlApmlReader, AnotherRootIsRefused) {
  const auto d = read_fml_apml("<apml>hello</apml>", "t.xml");
  ASSERT_FALSE(d);
  EXPECT_EQ(d.error().where.line, 1);
  EXPECT_NE(d.error().message.find("not <fml-apml>"), std::string::npos);
}

}  // namespace
}  // namespace fapc::intent
