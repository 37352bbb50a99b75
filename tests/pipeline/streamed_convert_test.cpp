// A .fap or .fba going to .fba, .mp4 and .fap is streamed (never held as frames,
// docs/architecture.md, "Streaming"); a second, independent way gives what it must give: the
// usual load and writers, byte for byte, error for error, over every .fap of the corpus (good,
// variant and bad), every .fba (good and bad) and .fba streams made from corpus files, with several
// encoder and flavour settings.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "fapc/pipeline/convert.hpp"
#include "pipeline_test_helpers.hpp"
#include "support/test_support.hpp"

namespace fapc {
namespace {

namespace fs = std::filesystem;
using pipeline::ConvertOptions;

std::string contents(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

using test::load_then_write;
using test::LoadedWay;

std::vector<ConvertOptions> settings() {
  std::vector<ConvertOptions> all(6);
  all[1].quant = 0;
  all[1].masks = "keep";
  all[2].quant = 7;
  all[2].intra_period = 10;
  all[2].ranges = "max";
  all[2].fap_flavour = FapFlavour::greta_java;
  all[3].fap_flavour = FapFlavour::semaine;
  all[4].limits.max_frames = 50;  // some corpus files are longer
  all[5].verify = true;           // each stream decoded and compared with the frames on the tape
  all[5].quant = 3;
  return all;
}

// Every file of these corpus folders with this extension.
std::vector<std::string> corpus_files(const std::vector<std::string>& folders, const std::string& extension) {
  std::vector<std::string> files;
  for (const std::string& folder : folders)
    for (const auto& entry : fs::recursive_directory_iterator(test::corpus_dir() + "/" + folder))
      if (entry.is_regular_file() && entry.path().extension() == extension) files.push_back(entry.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

// Converts `input` both ways to every output (all of them, then the .mp4 alone, then the .fap
// alone: a .fba to one .fap is decoded once) under every setting and compares; the number of
// outputs written and compared.
std::size_t expect_same_both_ways(const std::string& input, const test::TempFolder& tmp) {
  std::size_t compared = 0;
  const std::vector<std::vector<pipeline::OutputRequest>> requests = {
      {{tmp / "x.fap", ""}, {tmp / "x.fba", ""}, {tmp / "x.mp4", ""}},
      {{tmp / "x.mp4", ""}},
      {{tmp / "x.fap", ""}},
  };
  for (const ConvertOptions& options : settings()) {
    for (const auto& outputs : requests) {
      const LoadedWay expected = load_then_write(input, outputs, options);
      for (const auto& output : outputs) fs::remove(output.path);
      const pipeline::ConvertResult streamed = pipeline::convert(input, outputs, options);
      SCOPED_TRACE(input + " to " + std::to_string(outputs.size()) + " output(s)");
      EXPECT_TRUE(streamed.loaded.frames.frames.empty());  // streamed, not loaded
      if (expected.error) {
        EXPECT_FALSE(streamed.ok());
        if (streamed.error) {
          EXPECT_EQ(format_diagnostic(*streamed.error), format_diagnostic(*expected.error));
        }
      } else {
        EXPECT_TRUE(streamed.ok()) << format_diagnostic(*streamed.error);
        if (!streamed.ok()) continue;
      }
      for (std::size_t i = 0; i < outputs.size(); ++i) {
        if (i < expected.bytes.size()) {
          EXPECT_EQ(contents(outputs[i].path), expected.bytes[i]) << outputs[i].path;
          ++compared;
        } else {
          EXPECT_FALSE(fs::exists(outputs[i].path)) << outputs[i].path;
        }
      }
    }
  }
  return compared;
}

void expect_no_temporary_file(const test::TempFolder& tmp) {
  for (const auto& entry : fs::directory_iterator(tmp.path()))
    EXPECT_FALSE(entry.path().filename().string().starts_with(".fapc-tmp-")) << entry.path();
}

TEST(StreamedConvert, FapGivesTheBytesAndErrorsOfLoadingAndWriting) {
  const test::TempFolder tmp;
  const auto files = corpus_files({"fap", "fap-variants", "fap-bad"}, ".fap");
  EXPECT_GT(files.size(), 150u);
  std::size_t compared = 0;
  for (const std::string& input : files) compared += expect_same_both_ways(input, tmp);
  EXPECT_GT(compared, 2000u);  // most files convert under most settings
  expect_no_temporary_file(tmp);
}

TEST(StreamedConvert, FbaGivesTheBytesAndErrorsOfLoadingAndWriting) {
  const test::TempFolder tmp;
  std::vector<std::string> files = corpus_files({"fba", "fba-bad"}, ".fba");
  // Streams of other shapes: every tenth .fap of the corpus encoded, as the encoder makes them.
  const auto faps = corpus_files({"fap"}, ".fap");
  for (std::size_t k = 0; k < faps.size(); k += 10) {
    const std::string made = tmp / ("made-" + std::to_string(k) + ".fba");
    ASSERT_TRUE(pipeline::convert(faps[k], {{made, ""}}, ConvertOptions{}).ok()) << faps[k];
    files.push_back(made);
  }
  EXPECT_GT(files.size(), 20u);
  std::size_t compared = 0;
  for (const std::string& input : files) compared += expect_same_both_ways(input, tmp);
  EXPECT_GT(compared, 200u);
  expect_no_temporary_file(tmp);
}

TEST(StreamedConvert, AnEncoderErrorAboutOneFramePointsAtTheFramesLine) {
  // A value the bitstream cannot carry is found by the encoder, which sees frames, not lines: it
  // used to be reported against the file as a whole. Streamed (.fba, .mp4) and loaded alike.
  const test::TempFolder tmp;
  const std::string input = tmp / "far.fap";
  std::string mask = "0 0 1";  // FAP 3, open_jaw
  for (int fap = 4; fap <= 68; ++fap) mask += " 0";
  mask += "\n";
  std::ofstream(input) << "2.1 far 25 3\n" << mask << "0 10\n" << mask << "1 20\n" << mask << "2 2000000000\n";
  ConvertOptions loaded;
  loaded.facts = true;  // takes the usual way
  for (const ConvertOptions& options : {ConvertOptions{}, loaded}) {
    for (const char* output : {"x.fba", "x.mp4"}) {
      const pipeline::ConvertResult r = pipeline::convert(input, {{tmp / output, ""}}, options);
      ASSERT_FALSE(r.ok()) << output;
      EXPECT_EQ(r.error->where.file, input) << output;
      EXPECT_EQ(r.error->where.line, 7) << output;  // the third frame's value line
      EXPECT_FALSE(fs::exists(tmp / output));
    }
  }
}

}  // namespace
}  // namespace fapc
