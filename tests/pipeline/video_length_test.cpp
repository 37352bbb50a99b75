// A video's limits on its length (docs/security.md, "Resource limits"): asked of a script's timeline before
// its frames are rendered, and placed at the element that ends the animation; asked of frames read
// from a file at that file; the errors about the options (--size) name the output.
#include <gtest/gtest.h>

#include <fstream>

#include "fapc/pipeline/convert.hpp"
#include "pipeline_test_helpers.hpp"

namespace fapc {
namespace {

using test::TempFolder;

void write(const std::string& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

std::string xmto_lasting(const std::string& dur) {
  return "<?xml version=\"1.0\"?>\n<XMT-O xmlns=\"urn:mpeg:mpeg4:xmto:schema:2002\">\n<body>\n"
         "<animate attributeName=\"open_jaw\" values=\"0;100;0\" dur=\"" +
         dur + "\"/>\n</body>\n</XMT-O>\n";
}

TEST(VideoLength, AScriptOfFourHoursIsRefusedAtTheElementThatEndsIt) {
  TempFolder folder;
  const std::string input = folder / "long.xmt";
  write(input, xmto_lasting("4h"));
  for (const char* output : {"long.webm", "long.html"}) {
    const pipeline::ConvertResult result = pipeline::convert(input, {{folder / output, ""}}, {});
    ASSERT_TRUE(result.error) << output;
    EXPECT_EQ(result.error->kind, ErrorKind::limit_exceeded);
    // The element's place: only the check before rendering knows it (the writer has frames only).
    EXPECT_EQ(result.error->where.file, input);
    EXPECT_EQ(result.error->where.line, 4);
    EXPECT_NE(result.error->message.find("--max-video-pixels"), std::string::npos) << result.error->message;
    EXPECT_FALSE(std::filesystem::exists(folder / output));
  }
}

TEST(VideoLength, FramesReadFromAFileArePlacedAtTheFile) {
  TempFolder folder;
  const std::string input = folder / "gap.fap";
  std::string mask, zeros;
  for (int i = 0; i < 68; ++i) {
    mask += i ? " 1" : "1";
    zeros += " 0";
  }
  write(input, "2.1 gap 25 2\n" + mask + "\n0" + zeros + "\n" + mask + "\n100000" + zeros + "\n");
  const pipeline::ConvertResult result = pipeline::convert(input, {{folder / "gap.webm", ""}}, {});
  ASSERT_TRUE(result.error);
  EXPECT_EQ(result.error->kind, ErrorKind::limit_exceeded);
  EXPECT_EQ(result.error->where.file, input);
  EXPECT_EQ(result.error->where.line, 0);
}

TEST(VideoLength, AnOptionTheEncoderCannotTakeNamesTheOutput) {
  TempFolder folder;
  const std::string input = folder / "short.xmt";
  write(input, xmto_lasting("1s"));
  pipeline::ConvertOptions options;
  options.picture.width = 641;  // a 4:2:0 video needs even sides
  const pipeline::ConvertResult result = pipeline::convert(input, {{folder / "short.webm", ""}}, options);
  ASSERT_TRUE(result.error);
  EXPECT_EQ(result.error->kind, ErrorKind::usage);
  EXPECT_EQ(result.error->where.file, folder / "short.webm");
}

TEST(VideoLength, AVideoWithinTheLimitsIsWritten) {
  TempFolder folder;
  const std::string input = folder / "short.xmt";
  write(input, xmto_lasting("1s"));
  pipeline::ConvertOptions options;
  options.picture.width = 64;
  options.picture.height = 48;
  const pipeline::ConvertResult result = pipeline::convert(input, {{folder / "short.webm", ""}}, options);
  EXPECT_FALSE(result.error) << format_diagnostic(*result.error);
  EXPECT_TRUE(std::filesystem::exists(folder / "short.webm"));
}

}  // namespace
}  // namespace fapc
