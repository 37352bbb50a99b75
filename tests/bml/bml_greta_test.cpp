// Greta and SEMAINE reference names (docs/bml.md, "Greta references"): a face, head or gaze whose
// gretabml description names a reference of Greta's lexicon draws the rows of
// greta_references.tsv or intentions.tsv over its span, scaled by the expressivity parameters by
// the documented rule; unknown names keep their span with a placed warning.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "fapc/bml/bml.hpp"
#include "fapc/vocabulary/behaviour_lexicon.hpp"
#include "fapc/vocabulary/mapping_table.hpp"

namespace fapc::bml {
namespace {

// A Greta 0.x document (no namespace), one behaviour with its description.
std::string greta(const std::string& element, const std::string& reference, const std::string& parameters = "",
                  const std::string& attributes = "start=\"0\" end=\"2\"") {
  return "<bml id=\"b\">\n<" + element + " id=\"x\" " + attributes +
         ">\n<description level=\"1\" type=\"gretabml\">\n<reference>" + reference + "</reference>\n" + parameters +
         "</description>\n</" + element + ">\n</bml>\n";
}

BmlDocument read_ok(const std::string& text) {
  Result<BmlDocument> d = read_bml(text, "g.xml");
  EXPECT_TRUE(d) << (d ? "" : format_diagnostic(d.error()));
  return d ? std::move(*d) : BmlDocument{};
}

// The largest magnitude a target's clips reach (their keys), 0 when none moves it.
double peak(const BmlDocument& d, const std::string& target) {
  double out = 0;
  for (const Clip& c : d.timeline.clips)
    if (c.target.str() == target)
      for (const KeyPoint& k : c.curve.keys) out = std::max(out, std::abs(k.value));
  return out;
}

const Clip* first_clip(const BmlDocument& d, const std::string& target) {
  for (const Clip& c : d.timeline.clips)
    if (c.target.str() == target) return &c;
  return nullptr;
}

bool has_warning(const BmlDocument& d, const std::string& code, int line) {
  return std::any_of(d.warnings.begin(), d.warnings.end(),
                     [&](const Diagnostic& w) { return w.code == code && w.where.line == line; });
}

// fapc's table parses whole (a defect in it would leave the bundled lexicon empty), each row with a reason.
TEST(BmlGreta, TheBundledTableParses) {
  const std::string_view text = vocabulary::bundled_table_text("greta_references.tsv");
  Result<vocabulary::BehaviourLexicon> parsed = vocabulary::parse_behaviour_lexicon(text, "greta_references.tsv");
  ASSERT_TRUE(parsed) << format_diagnostic(parsed.error());
  EXPECT_GE(parsed->rows.size(), 30U);
  EXPECT_EQ(vocabulary::bundled_greta_references().rows.size(), parsed->rows.size());
  for (const vocabulary::LexiconRow& row : parsed->rows) EXPECT_FALSE(row.reason.empty()) << row.line;
}

TEST(BmlGreta, AnAffectIsTheEmotionOfTheIntentionLexicon) {
  const BmlDocument joy = read_ok(greta("face", "affect=joy"));
  EXPECT_GT(peak(joy, "raise_l_cornerlip"), 0);  // AU 12: the corners up
  EXPECT_GT(peak(joy, "lift_l_cheek"), 0);       // AU 6: the cheeks
  EXPECT_EQ(peak(joy, "raise_l_i_eyebrow"), 0);
  const BmlDocument sad = read_ok(greta("face", "affect=sadness"));
  EXPECT_GT(peak(sad, "raise_l_i_eyebrow"), 0);               // AU 1: the inner brows up
  const Clip* corner = first_clip(sad, "raise_l_cornerlip");  // AU 15: the corners down
  ASSERT_NE(corner, nullptr);
  EXPECT_LT(corner->curve.value_at(1.0), 0);
}

TEST(BmlGreta, ANumberedVariantIsItsDisplay) {
  const BmlDocument fear = read_ok(greta("face", "affect=fear"));
  const BmlDocument fear3 = read_ok(greta("face", "affect=fear3"));
  EXPECT_GT(peak(fear, "raise_l_i_eyebrow"), 0);
  EXPECT_DOUBLE_EQ(peak(fear3, "raise_l_i_eyebrow"), peak(fear, "raise_l_i_eyebrow"));
}

TEST(BmlGreta, ComplexExpressionsShareTheirParts) {
  const double joy = peak(read_ok(greta("face", "affect=joy")), "raise_l_cornerlip");
  const double sad = peak(read_ok(greta("face", "affect=sadness")), "raise_l_i_eyebrow");
  const BmlDocument both = read_ok(greta("face", "affect=complex:JOY_and_SADNESS"));
  EXPECT_NEAR(peak(both, "raise_l_cornerlip"), joy / 2, 1);
  EXPECT_NEAR(peak(both, "raise_l_i_eyebrow"), sad / 2, 1);
  // Sadness masked by joy: the smile whole, the sad brows leaking at 0.3.
  const BmlDocument masked = read_ok(greta("face", "affect=complex:SADNESS_maskedby_JOY"));
  EXPECT_NEAR(peak(masked, "raise_l_cornerlip"), joy, 1);
  EXPECT_NEAR(peak(masked, "raise_l_i_eyebrow"), sad * 0.3, 1);
}

TEST(BmlGreta, HeadReferencesTurnTheHead) {
  const BmlDocument d = read_ok(greta("head", "DOWN_ASIDE_RIGHT"));
  const Clip* pitch = first_clip(d, "head_pitch");
  const Clip* yaw = first_clip(d, "head_yaw");
  ASSERT_NE(pitch, nullptr);
  ASSERT_NE(yaw, nullptr);
  // Down is a positive pitch, the character's right a negative yaw (docs/bml.md, "What is drawn").
  EXPECT_GT(pitch->curve.value_at(1.0), 0);
  EXPECT_LT(yaw->curve.value_at(1.0), 0);
  EXPECT_GT(peak(read_ok(greta("head", "Nod_Middle")), "head_pitch"), 0);  // names compared without case
}

TEST(BmlGreta, GazeReferencesTurnTheEyes) {
  EXPECT_GT(peak(read_ok(greta("gaze", "gaze=look_left")), "yaw_l_eyeball"), 0);
  const BmlDocument ahead = read_ok(greta("gaze", "gaze=look_at"));
  EXPECT_EQ(peak(ahead, "yaw_l_eyeball"), 0);  // the listener is straight ahead
}

TEST(BmlGreta, SpatialExtentScalesTheAmount) {
  const double plain = peak(read_ok(greta("face", "affect=joy", "<SPC.value>0</SPC.value>")), "raise_l_cornerlip");
  const double wide = peak(read_ok(greta("face", "affect=joy", "<SPC.value>1</SPC.value>")), "raise_l_cornerlip");
  const double narrow = peak(read_ok(greta("face", "affect=joy", "<SPC.value>-1</SPC.value>")), "raise_l_cornerlip");
  EXPECT_NEAR(wide / plain, 1.5, 0.02);
  EXPECT_NEAR(narrow / plain, 0.5, 0.02);
  const double weak = peak(read_ok(greta("face", "affect=joy", "<intensity>0.5</intensity>")), "raise_l_cornerlip");
  EXPECT_NEAR(weak / plain, 0.5, 0.02);
}

TEST(BmlGreta, TemporalExtentScalesTheOnset) {
  // joy's rows peak at 0.2 of the span: 0.4 s into 2 s; TMP 1 halves the rise, TMP -1 makes it 1.5 times.
  auto rise = [](const std::string& tmp) {
    const BmlDocument d = read_ok(greta("face", "affect=joy", "<TMP.value>" + tmp + "</TMP.value>"));
    const Clip* c = first_clip(d, "raise_l_cornerlip");
    return c == nullptr || c->curve.keys.size() < 2 ? -1.0 : c->curve.keys[1].time;
  };
  EXPECT_NEAR(rise("0"), 0.4, 1e-9);
  EXPECT_NEAR(rise("1"), 0.2, 1e-9);
  EXPECT_NEAR(rise("-1"), 0.6, 1e-9);
}

TEST(BmlGreta, RepetitivityRepeatsHeadMovements) {
  auto swings = [](const std::string& rep) {
    const BmlDocument d = read_ok(greta("head", "Nod_Middle", "<REP.value>" + rep + "</REP.value>"));
    const Clip* c = first_clip(d, "head_pitch");
    if (c == nullptr) return 0;
    int extremes = 0;
    for (const KeyPoint& k : c->curve.keys) extremes += k.value != 0 ? 1 : 0;
    return extremes;
  };
  EXPECT_EQ(swings("0"), 1);
  EXPECT_EQ(swings("1"), 2);
  EXPECT_EQ(swings("-1"), 1);
}

TEST(BmlGreta, UnknownNamesKeepTheirSpanWithAPlacedWarning) {
  const BmlDocument d = read_ok(greta("face", "affect=nostalgia"));
  EXPECT_TRUE(has_warning(d, "bml.unknown_greta_name", 4));
  ASSERT_EQ(d.behaviours.size(), 1U);
  EXPECT_FALSE(d.behaviours[0].drawn);
  EXPECT_DOUBLE_EQ(d.behaviours[0].end, 2);
  EXPECT_TRUE(d.timeline.clips.empty());
  EXPECT_TRUE(has_warning(read_ok(greta("face", "affect=complex:JOY_and_NOSTALGIA")), "bml.unknown_greta_name", 4));
}

TEST(BmlGreta, ParametersWithoutACounterpartAreSaid) {
  const BmlDocument d = read_ok(greta("face", "affect=joy", "<FLD.value>1</FLD.value>\n<OPN.value>0.5</OPN.value>\n"));
  EXPECT_TRUE(has_warning(d, "bml.expressivity_not_drawn", 3));  // FLD, at the description
  EXPECT_TRUE(has_warning(d, "bml.expressivity_not_drawn", 6));  // OPN, at its element
  EXPECT_GT(peak(d, "raise_l_cornerlip"), 0);
}

TEST(BmlGreta, ParametersOutOfRangeArePlacedErrors) {
  for (const char* bad : {"<SPC.value>2</SPC.value>", "<TMP.value>fast</TMP.value>", "<intensity>-1</intensity>",
                          "<REP.value>nan</REP.value>"}) {
    Result<BmlDocument> d = read_bml(greta("face", "affect=joy", bad), "g.xml");
    ASSERT_FALSE(d) << bad;
    EXPECT_EQ(d.error().where.line, 5) << bad;
  }
}

}  // namespace
}  // namespace fapc::bml
