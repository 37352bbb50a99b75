#include "face/face_test_support.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "support/test_support.hpp"

namespace fapc::test {

void expect_golden_image(const std::string& path, const face::Image& actual) {
  const std::string full = corpus_dir() + "/" + path;
  const char* regenerate = std::getenv("FAPC_REGENERATE_GOLDEN");
  if (regenerate && std::string(regenerate) == "1") {
    std::filesystem::create_directories(std::filesystem::path(full).parent_path());
    std::ofstream(full, std::ios::binary) << *face::encode_png(actual);
    return;
  }
  if (!std::filesystem::exists(full)) {
    ADD_FAILURE() << "golden image " << path << " is missing; run with FAPC_REGENERATE_GOLDEN=1";
    return;
  }
  Result<face::Image> golden = face::decode_png(read_text(full), full);
  ASSERT_TRUE(golden) << golden.error().message;
  const face::ImageDifference d = face::compare_images(*golden, actual, kChannelTolerance);
  ASSERT_TRUE(d.same_size) << path << ": golden " << golden->width << "x" << golden->height << ", rendered "
                           << actual.width << "x" << actual.height;
  EXPECT_LE(double(d.pixels_over_tolerance), kPixelShare * double(actual.pixels.size()))
      << path << ": " << d.pixels_over_tolerance << " pixels differ by more than " << kChannelTolerance;
  EXPECT_LE(d.mean_channel_difference, kMeanTolerance) << path;
}

FapSequence constant_sequence(int fap, int value, int frames, int fps) {
  FapSequence s;
  s.fps = fps;
  for (int i = 0; i < frames; ++i) {
    FapFrame f;
    f.number = i;
    if (fap >= 3) f.set(fap, value);
    s.frames.push_back(f);
  }
  return s;
}

}  // namespace fapc::test
