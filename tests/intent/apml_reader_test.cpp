// The APML reader (docs/intentions.md), without a speech engine so that words fall in proportion
// to the text (the BML reader's rule, compared here with a BML speech of the same words).
#include <gtest/gtest.h>

#include <algorithm>

#include "fapc/intent/intent.hpp"

namespace fapc::intent {
namespace {

Result<IntentDocument> read(const std::string& body) { return read_apml("<apml>\n" + body + "\n</apml>\n", "t.xml"); }

// Where a BML speech of the same text puts a mark before word `before`.
double word_time(const std::string& text_with_mark) {
  const auto bml =
      bml::read_bml("<bml id=\"b\"><speech id=\"s\"><text>" + text_with_mark + "</text></speech></bml>", "t.bml");
  EXPECT_TRUE(bml) << bml.error().message;
  return bml->marks.at(0).time;
}

// How long a BML speech of the same text lasts.
double speech_length(const std::string& text) {
  const auto bml = bml::read_bml("<bml id=\"b\"><speech id=\"s\"><text>" + text + "</text></speech></bml>", "t.bml");
  EXPECT_TRUE(bml) << bml.error().message;
  return bml->behaviours.at(0).end;
}

const Intention* find(const IntentDocument& d, const std::string& type) {
  for (const Intention& i : d.intentions)
    if (i.type == type) return &i;
  return nullptr;
}

TEST(ApmlReader, AnIntentionStartsOnItsFirstWordAndEndsWithTheNextWord) {
  const auto d = read(
      R"(<performative type="announce">Whatever works for <emphasis x-pitchaccent="Hstar">you</emphasis> today</performative>)");
  ASSERT_TRUE(d) << d.error().message;
  const Intention* e = find(*d, "emphasis");
  ASSERT_NE(e, nullptr);
  EXPECT_EQ(e->value, "Hstar");
  EXPECT_NEAR(e->start, word_time("Whatever works for <sync id=\"m\"/>you today"), 1e-9);
  EXPECT_NEAR(e->end, word_time("Whatever works for you <sync id=\"m\"/>today"), 1e-9);
  const Intention* p = find(*d, "performative");
  ASSERT_NE(p, nullptr);
  EXPECT_NEAR(p->start, 0, 1e-9);
  EXPECT_GT(e->behaviours, 0);
}

TEST(ApmlReader, AttributesAddIntentionsWithTheirIntensity) {
  const auto d = read(
      R"(<rheme affect="sadness" intensity="0.4">so <emphasis x-pitchaccent="Hstar" deictic="self">me</emphasis></rheme>)");
  ASSERT_TRUE(d) << d.error().message;
  const Intention* affect = find(*d, "affect");
  ASSERT_NE(affect, nullptr);
  EXPECT_EQ(affect->value, "sadness");
  EXPECT_NEAR(affect->strength, 0.4, 1e-12);
  EXPECT_GT(affect->behaviours, 0);  // read as the emotion sadness
  const Intention* deictic = find(*d, "deictic");
  ASSERT_NE(deictic, nullptr);
  EXPECT_EQ(deictic->value, "self");
  EXPECT_EQ(deictic->where.line, 2);
  EXPECT_GT(deictic->where.column, 40);  // at the attribute
}

TEST(ApmlReader, APauseIsASilenceBetweenTheWords) {
  const auto with = read(R"(Hello there <pause sec="2.0"/><emphasis>again</emphasis>)");
  const auto without = read(R"(Hello there <emphasis>again</emphasis>)");
  ASSERT_TRUE(with && without);
  EXPECT_NEAR(find(*with, "emphasis")->start, speech_length("Hello there") + 2.0, 1e-9);
  EXPECT_NEAR(find(*without, "emphasis")->start, word_time("Hello there <sync id=\"m\"/>again"), 1e-9);
  EXPECT_LT(find(*without, "emphasis")->start, find(*with, "emphasis")->start - 1.5);
}

TEST(ApmlReader, ABoundaryIsAPointAfterItsWords) {
  const auto d = read(R"(Is it you<boundary type="HH"/>)");
  ASSERT_TRUE(d) << d.error().message;
  const Intention* b = find(*d, "boundary");
  ASSERT_NE(b, nullptr);
  EXPECT_NEAR(b->end - b->start, kPointSpanSeconds, 1e-9);
  EXPECT_GT(b->start, 0.3);
  EXPECT_GT(b->behaviours, 0);
}

TEST(ApmlReader, UnknownIntentionsAreWarningsWithTheirPlace) {
  const auto d = read(R"(<emphasis x-pitchaccent="Hstar" adjectival="tiny">small</emphasis>)");
  ASSERT_TRUE(d) << d.error().message;
  const auto w = std::find_if(d->warnings.begin(), d->warnings.end(),
                              [](const Diagnostic& x) { return x.code == "intent.unknown_intention"; });
  ASSERT_NE(w, d->warnings.end());
  EXPECT_EQ(w->where.line, 2);
  EXPECT_EQ(w->where.column, 33);
  EXPECT_NE(w->message.find("adjectival"), std::string::npos);
}

TEST(ApmlReader, BadNumbersAreRefusedAtTheirAttribute) {
  const auto pause = read(R"(a <pause sec="soon"/> b)");
  ASSERT_FALSE(pause);
  EXPECT_EQ(pause.error().where.line, 2);
  EXPECT_EQ(pause.error().where.column, 10);
  const auto intensity = read(R"(<theme affect="joy" intensity="7">a</theme>)");
  ASSERT_FALSE(intensity);
  EXPECT_EQ(intensity.error().where.column, 21);
  const auto root = read_apml("<fml-apml/>", "t.xml");
  ASSERT_FALSE(root);
}

}  // namespace
}  // namespace fapc::intent
