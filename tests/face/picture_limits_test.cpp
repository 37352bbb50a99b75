// Pixels per picture, per contact sheet and per video (docs/security.md, "Resource limits"):
// refused before anything is drawn or encoded, with the limit and its option in the error.
// Before these limits `render --size 7680x4320` to .webm took 3.6 GB and a 4-cell sheet at
// 7680x7680 1.2 GB; a four-hour animation to .webm ran for many minutes.
#include <gtest/gtest.h>

#include <chrono>

#include "face/face_test_support.hpp"
#include "fapc/face/pictures.hpp"
#include "fapc/face/webm.hpp"

namespace fapc::face {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

TEST(PictureLimits, APictureOfMorePixelsThanTheLimitIsRefused) {
  PictureOptions o;
  o.width = 7680;
  o.height = 4320;
  const Status checked = check_picture_options(o, "big.png");
  ASSERT_FALSE(checked);
  EXPECT_EQ(checked.error().kind, ErrorKind::limit_exceeded);
  EXPECT_EQ(checked.error().message,
            "--size 7680x4320 is 33177600 pixels a picture: more than the limit of 4194304 pixels "
            "(--max-frame-pixels N raises it)");
  o.limits.max_frame_pixels = 7680 * 4320;
  EXPECT_TRUE(check_picture_options(o, "big.png"));
  // 2048x2048 is exactly the default.
  EXPECT_TRUE(check_picture_options(PictureOptions{2048, 2048, {}, {}, {}, 0, false, {}, {}}, "x.png"));
}

TEST(PictureLimits, ASheetOfMorePixelsThanTheLimitIsRefusedBeforeItIsDrawn) {
  PictureOptions o;
  o.width = 7680;
  o.height = 7680;
  o.sheet = 4;  // 2 x 2 cells: 15360 x 15360
  o.limits.max_frame_pixels = std::int64_t{7680} * 7680;
  const auto start = std::chrono::steady_clock::now();
  Result<Image> sheet = render_picture(FaceTrack(test::constant_sequence(3, 100, 10)), o, "sheet.png");
  EXPECT_LT(seconds_since(start), 1.0);
  ASSERT_FALSE(sheet);
  EXPECT_EQ(sheet.error().kind, ErrorKind::limit_exceeded);
  EXPECT_EQ(sheet.error().message,
            "a contact sheet of 4 cells at --size 7680x7680 is 235929600 pixels: more than the limit of 134217728 "
            "pixels (--max-sheet-pixels N raises it)");
}

TEST(PictureLimits, AVideoTooLargeInAllIsRefusedBeforeAnyPictureIsEncoded) {
  // 10^5 frames at 25 fps, 640x480: 3.07e10 pixels, some minutes of encoding.
  const FaceTrack track(test::constant_sequence(3, 100, 100000));
  const auto start = std::chrono::steady_clock::now();
  Result<std::string> webm = encode_webm(track, VideoOptions{640, 480, 0, {}, {}}, nullptr, "long.webm");
  EXPECT_LT(seconds_since(start), 1.0);
  ASSERT_FALSE(webm);
  EXPECT_EQ(webm.error().kind, ErrorKind::limit_exceeded);
  EXPECT_NE(webm.error().message.find("the video would be 100000 pictures of 640x480"), std::string::npos)
      << webm.error().message;
  EXPECT_NE(webm.error().message.find("(--max-video-pixels N raises it)"), std::string::npos) << webm.error().message;
  // So is a picture larger than the limit, whatever the length.
  webm = encode_webm(FaceTrack(test::constant_sequence(3, 100, 2)), VideoOptions{7680, 4320, 0, {}, {}}, nullptr,
                     "big.webm");
  ASSERT_FALSE(webm);
  EXPECT_NE(webm.error().message.find("(--max-frame-pixels N raises it)"), std::string::npos) << webm.error().message;
}

TEST(PictureLimits, AVideoWithinTheLimitsIsEncodedAndReportsItsProgress) {
  std::int64_t last = 0, total = 0;
  VideoOptions o{64, 48, 0, {}, {}};
  o.progress = [&](std::int64_t done, std::int64_t all) {
    EXPECT_EQ(done, last + 1);
    last = done;
    total = all;
  };
  Result<std::string> webm = encode_webm(FaceTrack(test::constant_sequence(3, 100, 10)), o, nullptr, "short.webm");
  ASSERT_TRUE(webm) << webm.error().message;
  EXPECT_EQ(total, 10);
  EXPECT_EQ(last, 10);
}

}  // namespace
}  // namespace fapc::face
