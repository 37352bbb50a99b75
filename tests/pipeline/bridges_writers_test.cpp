// The bridge outputs: the viseme track of the speaking example against its FAP 1 stream, the
// ARKit and OpenFace CSVs read back by their readers, and the warnings naming what is lost.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "fapc/pipeline/registry.hpp"
#include "pipeline/pipeline_test_helpers.hpp"

namespace fapc {
namespace {

bool has_code(const Diagnostics& warnings, const std::string& code) {
  for (const Diagnostic& d : warnings)
    if (d.code == code) return true;
  return false;
}

// The OpenXR / Oculus names in FAP 1's order, written out here from that set's documentation.
const char* const kOpenXr[] = {"sil", "PP", "FF", "TH", "DD", "kk", "CH", "SS",
                               "nn",  "RR", "aa", "E",  "ih", "oh", "ou"};

TEST(BridgeWriters, TheSpeakingExamplesVisemeTrackNamesItsFap1StreamFrameByFrame) {
  const test::TempFolder tmp;
  const std::string input = test::corpus_dir() + "/examples/fml/two-languages.fml";
  const pipeline::ConvertResult result =
      pipeline::convert(input, {{tmp / "t.visemes.json", ""}, {tmp / "t.fap", ""}}, {});
  ASSERT_TRUE(result.ok()) << format_diagnostic(*result.error);
  // The FAP 1 stream as the .fap file carries it, read back.
  auto frames = pipeline::load(tmp / "t.fap", {});
  ASSERT_TRUE(frames.ok());
  const auto track = nlohmann::json::parse(test::read_text(tmp / "t.visemes.json"));
  const int fps = track["fps"];
  ASSERT_EQ(fps, frames->frames.fps);
  const auto& spans = track["visemes"];
  ASSERT_FALSE(spans.empty());
  std::size_t span = 0;
  int shown = 0, distinct_mask = 0, checked = 0;
  for (const FapFrame& frame : frames->frames.frames) {
    if (frame.has(1)) shown = frame.viseme.blend * 2 >= 63 ? frame.viseme.select1 : frame.viseme.select2;
    const double time = static_cast<double>(frame.number) / fps;
    while (span < spans.size() && spans[span]["end"].get<double>() <= time + 1e-9) ++span;
    ASSERT_LT(span, spans.size()) << "no span at " << time << " s";
    EXPECT_LE(spans[span]["start"].get<double>(), time + 1e-9);
    EXPECT_EQ(spans[span]["viseme"].get<std::string>(), kOpenXr[shown]) << "at " << time << " s";
    distinct_mask |= 1 << shown;
    ++checked;
  }
  EXPECT_GT(checked, 100);
  EXPECT_GT(__builtin_popcount(static_cast<unsigned>(distinct_mask)), 6);  // speech, not a held mouth
  EXPECT_TRUE(has_code(result.warnings, "visemes.faps_lost"));             // the smile's FAPs are not visemes
}

TEST(BridgeWriters, ArkitCsvReadsBackToTheFapsItCarries) {
  const test::TempFolder tmp;
  const std::string take =
      test::corpus_dir() + "/arkit/JMTechArt__Pipeline-Examples/MySlate_3_Jason_Millers_iPhone.csv";
  auto original = pipeline::load(take, {});
  ASSERT_TRUE(original.ok());
  const pipeline::ConvertResult written = pipeline::convert(take, {{tmp / "t.arkit.csv", ""}}, {});
  ASSERT_TRUE(written.ok()) << format_diagnostic(*written.error);
  auto back = pipeline::load(tmp / "t.arkit.csv", {});
  ASSERT_TRUE(back.ok()) << format_diagnostic(back.error());
  ASSERT_EQ(back->frames.frames.size(), original->frames.frames.size());
  // ARKit to FAPs to ARKit to FAPs: the shapes are fitted back, so the FAPs agree to a few units.
  for (std::size_t k = 0; k < back->frames.frames.size(); ++k) {
    for (int fap : {3, 19, 20, 12, 13, 31, 32, 23, 25}) {
      EXPECT_NEAR(back->frames.frames[k].value(fap), original->frames.frames[k].value(fap), 12)
          << "frame " << k << " FAP " << fap;
    }
  }
}

TEST(BridgeWriters, OpenFaceCsvReadsBackWithTheSameJawAndHead) {
  const test::TempFolder tmp;
  const std::string take = test::corpus_dir() + "/openface/isir__greta/AUParser_example.csv";
  auto original = pipeline::load(take, {});
  ASSERT_TRUE(original.ok());
  ASSERT_TRUE(pipeline::convert(take, {{tmp / "t.au.csv", ""}}, {}).ok());
  const std::string text = test::read_text(tmp / "t.au.csv");
  EXPECT_EQ(text.substr(0, 31), "frame, face_id, timestamp, conf");
  auto back = pipeline::load(tmp / "t.au.csv", {});
  ASSERT_TRUE(back.ok()) << format_diagnostic(back.error());
  ASSERT_EQ(back->frames.frames.size(), original->frames.frames.size());
  for (std::size_t k = 0; k < back->frames.frames.size(); ++k) {
    for (int fap : {3, 48, 49, 50, 23, 25}) {
      // Intensities are written to 2 decimals, angles to 1 mrad: a few units of rounding.
      EXPECT_NEAR(back->frames.frames[k].value(fap), original->frames.frames[k].value(fap), 60)
          << "frame " << k << " FAP " << fap;
    }
  }
}

TEST(BridgeWriters, WhatAFormatCannotCarryIsNamed) {
  const test::TempFolder tmp;
  // anger.fap moves FAPs ARKit has no shape for? Whatever it moves, the warnings list only FAPs
  // outside what the output carries, and the track warns that it keeps FAP 1 alone.
  const std::string input = test::corpus_dir() + "/examples/fap/anger.fap";
  const pipeline::ConvertResult result =
      pipeline::convert(input, {{tmp / "a.visemes.csv", ""}, {tmp / "a.arkit.csv", ""}}, {});
  ASSERT_TRUE(result.ok());
  EXPECT_TRUE(has_code(result.warnings, "visemes.faps_lost"));
  EXPECT_TRUE(has_code(result.warnings, "visemes.no_viseme"));
  EXPECT_EQ(test::read_text(tmp / "a.visemes.csv").substr(0, 23), "start,end,viseme,mpeg4\n");
  // Under --strict the losses refuse the outputs before any is written.
  pipeline::ConvertOptions strict;
  strict.strict = true;
  const pipeline::ConvertResult refused = pipeline::convert(input, {{tmp / "b.visemes.csv", ""}}, strict);
  EXPECT_FALSE(refused.ok());
  EXPECT_TRUE(refused.written.empty());
}

}  // namespace
}  // namespace fapc
