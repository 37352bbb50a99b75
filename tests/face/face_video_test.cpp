// The .webm as outside tools see it (ffprobe, ffmpeg), and the .html page in headless Chromium.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "face/face_test_support.hpp"
#include "fapc/face/image.hpp"
#include "fapc/face/preview_page.hpp"
#include "support/test_support.hpp"

namespace fapc::face {
namespace {

// figure3.mimic lasts 40 s: 1000 frames at 25 fps.
TEST(FaceVideo, WebmDecodesWithTheRightFrameCountAndDuration) {
  const std::string out = test::binary_dir() + "/face-figure3.webm";
  const test::CommandRun run =
      test::run_fapc("render corpus/examples/mimic/figure3.mimic -o " + out + " --size 320x240");
  ASSERT_EQ(run.exit_status, 0) << run.err;
  EXPECT_EQ(run.err, "");  // libav's own logging stays quiet
  const test::CommandRun probe = test::run_shell(
      "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
      "stream=codec_name,width,height,nb_read_frames:format=duration -of json " +
      out);
  ASSERT_EQ(probe.exit_status, 0) << probe.err;
  const auto facts = nlohmann::json::parse(probe.out);
  const auto& stream = facts["streams"][0];
  EXPECT_EQ(stream["codec_name"], "vp9");
  EXPECT_EQ(stream["width"], 320);
  EXPECT_EQ(stream["height"], 240);
  EXPECT_EQ(stream["nb_read_frames"], "1000");
  EXPECT_NEAR(std::stod(facts["format"]["duration"].get<std::string>()), 40.0, 0.5 / 25);
  const test::CommandRun decode = test::run_shell("ffmpeg -v error -i " + out + " -f null -");
  EXPECT_EQ(decode.exit_status, 0);
  EXPECT_EQ(decode.err, "");
}

TEST(FaceVideo, FrameRateOptionResamplesTheAnimation) {
  const std::string out = test::binary_dir() + "/face-figure3-10fps.webm";
  ASSERT_EQ(test::run_fapc("render corpus/examples/mimic/figure3.mimic -o " + out + " --size 160x120 --frame-rate 10")
                .exit_status,
            0);
  const test::CommandRun probe = test::run_shell(
      "ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames -of csv=p=0 " + out);
  EXPECT_EQ(probe.out, "400\n");
}

TEST(FaceVideo, OddSizesAreRefusedForVideo) {
  const test::CommandRun run = test::run_fapc("render corpus/examples/mimic/figure3.mimic -o " + test::binary_dir() +
                                              "/odd.webm --size 321x240");
  EXPECT_EQ(run.exit_status, 2);  // a usage error (ErrorKind::usage), docs/cli.md
  EXPECT_NE(run.err.find("even sides"), std::string::npos) << run.err;
}

// The preview page in headless Chromium: seek to a time, then the video area must show the .png
// of that frame (within a video codec's tolerance) and the cursor must sit at that frame's time.
TEST(FacePreviewPage, ChromiumShowsTheFrameAndTheCursorAtTheSeekedTime) {
  const std::string dir = test::binary_dir() + "/face-preview";
  std::filesystem::create_directories(dir);
  const std::string page = dir + "/figure3.html";
  ASSERT_EQ(test::run_fapc("render corpus/examples/mimic/figure3.mimic -o " + page + " --size 320x240").exit_status, 0);
  // Frame 272 (10.88 s), seeking into its middle so rounding cannot land on a neighbour.
  const int frame = 272;
  const double seek = (frame + 0.5) / 25;
  ASSERT_EQ(test::run_fapc("render corpus/examples/mimic/figure3.mimic -o " + dir +
                           "/expected.png --size 320x240 --frame " + std::to_string(frame))
                .exit_status,
            0);
  const test::CommandRun shot =
      test::run_shell("python3 " + test::source_dir() + "/tests/face/browser_screenshot.py chromium 'file://" + page +
                      "#t=" + std::to_string(seek) + "' " + dir + "/shot.png 0 0 320 240");
  ASSERT_EQ(shot.exit_status, 0) << shot.err << shot.out;
  const auto state = nlohmann::json::parse(shot.out);
  EXPECT_NEAR(std::stod(state["data"]["cursorTime"].get<std::string>()), frame / 25.0, 1e-9);
  // The cursor line's x on the plot: the time axis runs from the margin over 999 frames.
  const double axis = kPlotWidth - 2 * kPlotMargin;
  EXPECT_NEAR(std::stod(state["data"]["cursorX"].get<std::string>()), kPlotMargin + axis * (frame / 25.0) / 40.0, 1e-6);

  Result<Image> expected = decode_png(test::read_text(dir + "/expected.png"), "expected.png");
  Result<Image> seen = decode_png(test::read_text(dir + "/shot.png"), "shot.png");
  ASSERT_TRUE(expected && seen);
  // Lossy VP9 and the browser's colour conversion: compared on the mean, with few large misses.
  const ImageDifference d = compare_images(*expected, *seen, 48);
  ASSERT_TRUE(d.same_size);
  EXPECT_LE(d.mean_channel_difference, 3.0);
  EXPECT_LE(double(d.pixels_over_tolerance), 0.01 * double(expected->pixels.size()));
  // And not some other frame: the neutral face (frame 0) differs clearly from this one.
  ASSERT_EQ(
      test::run_fapc("render corpus/examples/mimic/figure3.mimic -o " + dir + "/frame0.png --size 320x240 --frame 0")
          .exit_status,
      0);
  Result<Image> first = decode_png(test::read_text(dir + "/frame0.png"), "frame0.png");
  ASSERT_TRUE(first);
  EXPECT_GT(compare_images(*first, *seen, 48).pixels_over_tolerance, d.pixels_over_tolerance * 3 + 200);
}

}  // namespace
}  // namespace fapc::face
