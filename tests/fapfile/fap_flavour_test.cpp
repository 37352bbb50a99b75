// The .fap flavours (docs/fap-files.md, "Flavours"): every corpus file written in each flavour is
// read as intended by that family's strict checker (fap_family_checkers.hpp, written from the
// programs' readers in docs/fap-files.md section 3), shows the checker the values written, and
// reads back through fapc's reader to the same values. A flavour that cannot carry a file refuses
// it, naming the frame. The sanitizer build (FAPC_SANITIZED_BUILD) takes every eighth file only
// (docs/testing.md).
#include <gtest/gtest.h>

#include <array>
#include <cstdio>

#include "fap_family_checkers.hpp"
#include "fapc/codec/fap_file.hpp"
#include "support/corpus_sweep.hpp"

namespace fapc {
namespace {

struct FlavourCase {
  FapFlavour flavour;
  test::Family family;
  bool single_fap12;
};

const FlavourCase kCases[] = {
    {FapFlavour::safe, test::Family::safe, false},           {FapFlavour::xface, test::Family::xface, false},
    {FapFlavour::greta_cpp, test::Family::greta_cpp, false}, {FapFlavour::greta_java, test::Family::greta_java, true},
    {FapFlavour::vreng, test::Family::vreng, true},          {FapFlavour::semaine, test::Family::semaine, true},
};

// What one value of FAP 1 / FAP 2 stands for (fap-files.md: Greta's form, one select shown alone).
bool single_value_form(const FapFrame& f) {
  const bool viseme = !f.has(1) || (f.viseme.select2 == 0 && f.viseme.blend == 63 && f.viseme.def == 0);
  const bool expression =
      !f.has(2) || (f.expression.intensity1 == 63 && f.expression.select2 == 0 && f.expression.intensity2 == 0 &&
                    f.expression.init_face == 0 && f.expression.def == 0);
  return viseme && expression;
}

// The input frame shown at written position j: frames are renumbered from 0 and gaps filled by
// repeating the frame before.
const FapFrame& frame_at(const FapSequence& s, long long j) {
  std::size_t i = 0;
  while (i + 1 < s.frames.size() && s.frames[i + 1].number - s.frames.front().number <= j) ++i;
  return s.frames[i];
}

std::string differs(const test::SeenFrame& seen, const FapFrame& f, bool single) {
  for (std::size_t i = 0; i < 68; ++i)
    if (seen.mask.test(i) != f.mask.test(i)) return "mask bit " + std::to_string(i + 1);
  if (f.has(1)) {
    const std::vector<long long> want =
        single ? std::vector<long long>{f.viseme.select1}
               : std::vector<long long>{f.viseme.select1, f.viseme.select2, f.viseme.blend, f.viseme.def};
    if (seen.fap1 != want) return "FAP 1";
  }
  if (f.has(2)) {
    const ExpressionFields& e = f.expression;
    const std::vector<long long> want =
        single ? std::vector<long long>{e.select1}
               : std::vector<long long>{e.select1, e.intensity1, e.select2, e.intensity2, e.init_face, e.def};
    if (seen.fap2 != want) return "FAP 2";
  }
  std::size_t k = 0;
  for (int fap = 3; fap <= kFapCount; ++fap)
    if (f.has(fap) && (k >= seen.values.size() || seen.values[k++] != f.value(fap)))
      return "FAP " + std::to_string(fap);
  return {};
}

TEST(FapFlavour, EveryCorpusFileSatisfiesEachFamilysChecker) {
  ASSERT_GE(test::all_good_corpus_fap_files().size(), 196u);
  const auto files = test::sweep_fap_files();
  std::array<std::size_t, std::size(kCases)> written{}, refused{};
  for (const std::string& path : files) {
    auto read = read_fap_text(test::read_text(path), path);
    ASSERT_TRUE(read.ok()) << path;
    const FapSequence& input = read->sequence;
    for (std::size_t n = 0; n < std::size(kCases); ++n) {
      const FlavourCase& c = kCases[n];
      FapWriteOptions options;
      options.flavour = c.flavour;
      auto text = write_fap_flavour(input, options);
      const std::string label = path + " as " + std::string(fap_flavour_name(c.flavour));
      bool carried = true;
      if (c.single_fap12)
        for (const FapFrame& f : input.frames) carried = carried && single_value_form(f);
      if (c.flavour == FapFlavour::semaine) carried = carried && 1000 % input.fps == 0;
      ASSERT_EQ(text.ok(), carried) << label;
      if (!text.ok()) {
        EXPECT_EQ(text.error().kind, ErrorKind::unsupported) << label;
        ++refused[n];
        continue;
      }
      ++written[n];
      const test::Seen seen = test::read_as(c.family, *text);
      ASSERT_EQ(seen.error, "") << label;
      const long long frames = input.frames.empty() ? 0 : input.frames.back().number - input.frames.front().number + 1;
      ASSERT_EQ(static_cast<long long>(seen.frames.size()), frames) << label;
      for (long long j = 0; j < frames; ++j)
        ASSERT_EQ(differs(seen.frames[static_cast<std::size_t>(j)], frame_at(input, j), c.single_fap12), "")
            << label << " frame " << j;
      if (seen.fps != 0 && frames > 1) {
        EXPECT_EQ(seen.fps, input.fps) << label;
      }

      // Round trip through fapc's own reader: the same frames and values.
      auto again = read_fap_text(*text, "again.fap");
      ASSERT_TRUE(again.ok()) << label << ": " << format_diagnostic(again.error());
      ASSERT_EQ(static_cast<long long>(again->sequence.frames.size()), frames) << label;
      for (long long j = 0; j < frames; ++j)
        EXPECT_TRUE(again->sequence.frames[static_cast<std::size_t>(j)].same_content(frame_at(input, j)))
            << label << " frame " << j;
      if (frames > 1) {
        EXPECT_EQ(again->sequence.fps, input.fps) << label;
      }
    }
  }
  for (std::size_t n = 0; n < std::size(kCases); ++n)
    std::printf("%-10s %zu corpus files written and passed their family's checker, %zu refused\n",
                std::string(fap_flavour_name(kCases[n].flavour)).c_str(), written[n], refused[n]);
}

FapSequence with_high_level(VisemeFields viseme, int fps = 25) {
  FapSequence s{"high level", fps, {}};
  for (int k = 0; k < 2; ++k) {
    FapFrame f;
    f.number = k;
    f.mask.set(0);
    f.viseme = viseme;
    f.set(3, 100 * k);
    s.frames.push_back(f);
  }
  return s;
}

TEST(FapFlavour, SingleValueFamiliesRefuseWhatOneValueCannotSay) {
  const FapSequence blended = with_high_level({3, 7, 40, 0});
  for (const FapFlavour flavour : {FapFlavour::greta_java, FapFlavour::vreng, FapFlavour::semaine}) {
    FapWriteOptions options;
    options.flavour = flavour;
    auto text = write_fap_flavour(blended, options);
    ASSERT_FALSE(text.ok());
    EXPECT_EQ(text.error().kind, ErrorKind::unsupported);
    EXPECT_NE(text.error().message.find("frame 0: FAP 1"), std::string::npos) << text.error().message;
  }
  for (const FapFlavour flavour : {FapFlavour::safe, FapFlavour::xface, FapFlavour::greta_cpp}) {
    FapWriteOptions options;
    options.flavour = flavour;
    auto text = write_fap_flavour(blended, options);
    ASSERT_TRUE(text.ok());
    // Checked by hand: mask, then frame 0, the four viseme fields, FAP 3.
    EXPECT_NE(text->find("\n0 3 7 40 0 0 \n"), std::string::npos);
  }
  // A viseme shown alone is one value: Greta Java's 69-token masks and its single value.
  FapWriteOptions java;
  java.flavour = FapFlavour::greta_java;
  auto text = write_fap_flavour(with_high_level({5, 0, 63, 0}), java);
  ASSERT_TRUE(text.ok());
  EXPECT_EQ(text->substr(0, text->find('\n')), "2.1 high_level 25 2");
  EXPECT_NE(text->find(" 0 0 \n1 5 100 \n"), std::string::npos) << *text;
}

TEST(FapFlavour, SemaineNumbersFramesInMilliseconds) {
  FapWriteOptions options;
  options.flavour = FapFlavour::semaine;
  auto text = write_fap_flavour(with_high_level({5, 0, 63, 0}, 10), options);
  ASSERT_TRUE(text.ok());
  EXPECT_EQ(text->substr(0, 2), "0\n");
  EXPECT_NE(text->find("\n100 5 0 \n"), std::string::npos) << *text;  // 10 fps: 100 ms a frame
  EXPECT_NE(text->find("\n200 5 100 \n"), std::string::npos) << *text;
  auto thirty = write_fap_flavour(with_high_level({5, 0, 63, 0}, 30), options);
  ASSERT_FALSE(thirty.ok());
  EXPECT_NE(thirty.error().message.find("30 frames per second"), std::string::npos);
}

TEST(FapFlavour, NamesRoundTrip) {
  for (const FlavourCase& c : kCases) EXPECT_EQ(fap_flavour_named(fap_flavour_name(c.flavour)), c.flavour);
  EXPECT_FALSE(fap_flavour_named("greta").has_value());
  EXPECT_EQ(fap_flavour_names(), "safe|xface|greta-cpp|greta-java|vreng|semaine");
}

}  // namespace
}  // namespace fapc

namespace fapc {
namespace {

// The checkers can fail: each refuses the forms its family misreads (docs/fap-files.md section 3).
TEST(FapFlavour, CheckersRefuseFormsTheirFamilyMisreads) {
  const FapSequence blended = with_high_level({3, 7, 40, 0});
  FapWriteOptions options;
  const std::string safe = *write_fap_flavour(blended, options);
  // 4 viseme fields where one value is read; 68 mask tokens where Greta Java writes 69.
  EXPECT_NE(test::read_as(test::Family::vreng, safe).error, "");
  EXPECT_NE(test::read_as(test::Family::greta_java, safe).error, "");
  EXPECT_NE(test::read_as(test::Family::semaine, safe).error, "");  // a header, no time line
  options.flavour = FapFlavour::greta_java;
  const std::string java = *write_fap_flavour(with_high_level({5, 0, 63, 0}), options);
  EXPECT_NE(test::read_as(test::Family::xface, java).error, "");  // Xface reads the 69th token as a frame number
  // Tabs (VREng does not parse them), CRLF, a comment after the header, a name with a space.
  std::string tabs = *write_fap_flavour(with_high_level({5, 0, 63, 0}), {});
  tabs[tabs.rfind("\n1 ") + 2] = '\t';
  EXPECT_NE(test::read_as(test::Family::vreng, tabs).error, "");
  std::string crlf = safe;
  crlf.insert(crlf.find('\n'), "\r");
  EXPECT_NE(test::read_as(test::Family::xface, crlf).error, "");
  std::string comment = safe;
  comment.insert(comment.find('\n') + 1, "# note\n");
  EXPECT_NE(test::read_as(test::Family::greta_java, comment).error, "");
  std::string spaced = safe;
  spaced.replace(0, spaced.find('\n'), "2.1 high level 25 2");
  EXPECT_NE(test::read_as(test::Family::greta_cpp, spaced).error, "");
  EXPECT_EQ(test::read_as(test::Family::greta_cpp, safe).error, "");
}

}  // namespace
}  // namespace fapc
