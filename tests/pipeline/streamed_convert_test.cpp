// A .fap going to .fba and .fap is streamed (never held as frames, docs/architecture.md,
// "Streaming long frame files"); a second, independent way gives what it must give: the usual
// load and writers, byte for byte, error for error, over every .fap of the corpus and several
// encoder and flavour settings.
#include <gtest/gtest.h>

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

// The usual way: load, then each writer's bytes; the first error.
struct Usual {
  std::vector<std::string> bytes;
  std::optional<Diagnostic> error;
};

Usual usual_way(const std::string& input, const std::vector<pipeline::OutputRequest>& outputs,
                const ConvertOptions& options) {
  Usual out;
  auto loaded = pipeline::load(input, options);
  if (!loaded) {
    out.error = loaded.error();
    return out;
  }
  loaded->origin = input;
  for (const auto& request : outputs) {
    auto bytes = pipeline::render_output(*loaded, request, options);
    if (!bytes) {
      out.error = bytes.error();
      return out;
    }
    out.bytes.push_back(*bytes);
  }
  return out;
}

std::vector<ConvertOptions> settings() {
  std::vector<ConvertOptions> all(5);
  all[1].quant = 0;
  all[1].masks = "keep";
  all[2].quant = 7;
  all[2].intra_period = 10;
  all[2].ranges = "max";
  all[2].fap_flavour = FapFlavour::greta_java;
  all[3].fap_flavour = FapFlavour::semaine;
  all[4].limits.max_frames = 50;  // some corpus files are longer
  return all;
}

TEST(StreamedConvert, GivesTheBytesAndErrorsOfLoadingAndWriting) {
  const test::TempFolder tmp;
  std::size_t files = 0;
  for (const auto& entry : fs::recursive_directory_iterator(test::corpus_dir() + "/fap")) {
    if (!entry.is_regular_file() || entry.path().extension() != ".fap") continue;
    ++files;
    for (const ConvertOptions& options : settings()) {
      const std::vector<pipeline::OutputRequest> outputs = {{tmp / "x.fap", ""}, {tmp / "x.fba", ""}};
      const Usual expected = usual_way(entry.path().string(), outputs, options);
      fs::remove(tmp / "x.fap");
      fs::remove(tmp / "x.fba");
      const pipeline::ConvertResult streamed = pipeline::convert(entry.path().string(), outputs, options);
      SCOPED_TRACE(entry.path().string());
      EXPECT_TRUE(streamed.loaded.frames.frames.empty());  // streamed, not loaded
      if (expected.error) {
        ASSERT_FALSE(streamed.ok());
        EXPECT_EQ(format_diagnostic(*streamed.error), format_diagnostic(*expected.error));
      } else {
        ASSERT_TRUE(streamed.ok()) << format_diagnostic(*streamed.error);
      }
      for (std::size_t i = 0; i < outputs.size(); ++i) {
        if (i < expected.bytes.size()) EXPECT_EQ(contents(outputs[i].path), expected.bytes[i]) << outputs[i].path;
        else EXPECT_FALSE(fs::exists(outputs[i].path)) << outputs[i].path;
      }
    }
  }
  EXPECT_GT(files, 100u);
  for (const auto& entry : fs::directory_iterator(tmp.path()))  // no temporary file left behind
    EXPECT_FALSE(entry.path().filename().string().starts_with(".fapc-tmp-")) << entry.path();
}

TEST(StreamedConvert, AnEncoderErrorAboutOneFramePointsAtTheFramesLine) {
  // A value the bitstream cannot carry is found by the encoder, which sees frames, not lines: it
  // used to be reported against the file as a whole. Streamed (.fba) and loaded (.mp4) alike.
  const test::TempFolder tmp;
  const std::string input = tmp / "far.fap";
  std::string mask = "0 0 1";  // FAP 3, open_jaw
  for (int fap = 4; fap <= 68; ++fap) mask += " 0";
  mask += "\n";
  std::ofstream(input) << "2.1 far 25 3\n" << mask << "0 10\n" << mask << "1 20\n" << mask << "2 2000000000\n";
  for (const char* output : {"x.fba", "x.mp4"}) {
    const pipeline::ConvertResult r = pipeline::convert(input, {{tmp / output, ""}}, ConvertOptions{});
    ASSERT_FALSE(r.ok()) << output;
    EXPECT_EQ(r.error->where.file, input) << output;
    EXPECT_EQ(r.error->where.line, 7) << output;  // the third frame's value line
    EXPECT_FALSE(fs::exists(tmp / output));
  }
}

}  // namespace
}  // namespace fapc
