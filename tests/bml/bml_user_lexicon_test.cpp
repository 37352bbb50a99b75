// A user's lexicon (--lexicon) in BML (docs/bml.md, "A lexicon of your own"): its faceLexeme rows
// draw the lexemes they name (replacing bml_lexemes.tsv's rows, or adding lexemes), its face,
// head and gaze rows the Greta references they name; a bad row is refused at its line. Measured
// on the frames of the real pipeline.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "intent/intent_test_support.hpp"

namespace fapc {
namespace {

constexpr int kRaiseLeftInnerBrow = 31;
constexpr int kRaiseLeftCornerLip = 12;
constexpr int kHeadPitch = 48;
const std::string kHeader = "intention\tvalue\tbehaviour\tname\tamount\tstart\tready\trelax\tend\treason\n";

std::string write(const std::string& name, const std::string& text) { return test::write_temp("bml-" + name, text); }

// `lexicon` empty: fapc's own tables alone. (Not test::load_at_25: GCC 12 at -O2 sees its
// optional<string> as maybe uninitialized when inlined here.)
Result<pipeline::Loaded> load(const std::string& path, const std::string& lexicon = "") {
  static const pipeline::ConvertOptions kAt25 = [] {
    pipeline::ConvertOptions o;
    o.fps = 25;
    return o;
  }();
  pipeline::ConvertOptions options = kAt25;
  if (!lexicon.empty()) options.lexicon.emplace(lexicon);
  return pipeline::load(path, options);
}

double fap_at(const pipeline::Loaded& loaded, int fap, double seconds) {
  return test::fap_at(loaded.frames, fap, seconds);
}

// One face lexeme from 0 to 2 s: at its peak (1 s) the face shows it whole.
std::string face(const std::string& lexeme) {
  return write(lexeme + ".bml",
               "<bml xmlns=\"http://www.bml-initiative.org/bml/bml-1.0\" id=\"b\">\n"
               "  <faceLexeme id=\"f\" lexeme=\"" +
                   lexeme + "\" start=\"0\" end=\"2\"/>\n</bml>\n");
}

TEST(BmlUserLexicon, ARowReplacesTheLexemeItNames) {
  const std::string doc = face("RAISE_BROWS");
  Result<pipeline::Loaded> own = load(doc);
  ASSERT_TRUE(own) << own.error().message;
  EXPECT_GT(fap_at(*own, kRaiseLeftInnerBrow, 1), 0);
  EXPECT_EQ(fap_at(*own, kRaiseLeftCornerLip, 1), 0);

  const std::string lexicon =
      write("brows-smile.tsv", kHeader + "faceLexeme\tRAISE_BROWS\tau\t12\t1\t0\t0.2\t0.8\t1\tthis one smiles\n");
  Result<pipeline::Loaded> user = load(doc, lexicon);
  ASSERT_TRUE(user) << user.error().message;
  EXPECT_EQ(fap_at(*user, kRaiseLeftInnerBrow, 1), 0) << "the brows still rise";
  EXPECT_GT(fap_at(*user, kRaiseLeftCornerLip, 1), 0) << "the corners do not";
  EXPECT_EQ(fap_at(*user, kRaiseLeftCornerLip, 2.1), 0) << "moves after the face's end";
}

TEST(BmlUserLexicon, ARowAddsALexemeAndOthersKeepFapcsRows) {
  const std::string lexicon =
      write("smile.tsv", kHeader + "faceLexeme\tSMILE\tlexeme\tRAISE_MOUTH_CORNERS\t1\t0\t0.2\t0.8\t1\tours\n");
  Result<pipeline::Loaded> unknown = load(face("SMILE"));
  ASSERT_TRUE(unknown) << unknown.error().message;
  EXPECT_EQ(fap_at(*unknown, kRaiseLeftCornerLip, 1), 0);
  Result<pipeline::Loaded> smile = load(face("SMILE"), lexicon);
  ASSERT_TRUE(smile) << smile.error().message;
  EXPECT_GT(fap_at(*smile, kRaiseLeftCornerLip, 1), 0);
  Result<pipeline::Loaded> brows = load(face("RAISE_BROWS"), lexicon);  // not named: fapc's rows
  ASSERT_TRUE(brows) << brows.error().message;
  EXPECT_GT(fap_at(*brows, kRaiseLeftInnerBrow, 1), 0);
}

TEST(BmlUserLexicon, ARowNamesAGretaReference) {
  const std::string doc = write("greta.bml",
                                "<bml id=\"b\">\n  <head id=\"h\" start=\"0\" end=\"2\"><description type=\"gretabml\">"
                                "<reference>MyNod</reference></description></head>\n</bml>\n");
  Result<pipeline::Loaded> own = load(doc);
  ASSERT_TRUE(own) << own.error().message;
  for (const FapFrame& f : own->frames.frames) EXPECT_FALSE(f.has(kHeadPitch) && f.value(kHeadPitch) != 0);
  const std::string lexicon =
      write("mynod.tsv", kHeader + "head\tMyNod\thead\tNOD\t1\t0\t0.3\t0.7\t1\tthe character's own nod\n");
  Result<pipeline::Loaded> user = load(doc, lexicon);
  ASSERT_TRUE(user) << user.error().message;
  double deepest = 0;
  for (const FapFrame& f : user->frames.frames)
    if (f.has(kHeadPitch)) deepest = std::max(deepest, static_cast<double>(f.value(kHeadPitch)));
  EXPECT_GT(deepest, 0) << "the head does not nod";
}

TEST(BmlUserLexicon, ABadRowIsRefusedAtItsLine) {
  const std::string lexicon =
      write("bad.tsv", kHeader + "faceLexeme\tSMILE\tlexeme\tRAISE_MOUTH_CORNERS\t1\t0\t0.2\t0.8\t1\tok\n" +
                           "faceLexeme\tGRIN\tlexeme\tNO_SUCH_LEXEME\t1\t0\t0.2\t0.8\t1\tr\n");
  Result<pipeline::Loaded> loaded = load(face("SMILE"), lexicon);
  ASSERT_FALSE(loaded);
  EXPECT_EQ(loaded.error().where.file, lexicon);
  EXPECT_EQ(loaded.error().where.line, 3);
  EXPECT_EQ(loaded.error().where.column, 24);  // the name's cell, after 23 bytes
  EXPECT_EQ(loaded.error().code, "vocabulary.unknown_name");
}

}  // namespace
}  // namespace fapc
