// A picture in memory: 32-bit pixels, 0xAARRGGBB in native byte order (cairo's ARGB32; on a
// little-endian machine the bytes are B, G, R, A), rows top to bottom with no padding.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "fapc/codec/diagnostic.hpp"

namespace fapc::face {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint32_t> pixels;

  Image() = default;
  Image(int w, int h) : width(w), height(h), pixels(static_cast<std::size_t>(w) * h, 0xff000000u) {}
  std::uint32_t at(int x, int y) const { return pixels[static_cast<std::size_t>(y) * width + x]; }
};

// PNG bytes of an opaque image, and back (for tests and golden comparisons).
Result<std::string> encode_png(const Image& image);
Result<Image> decode_png(std::string_view bytes, const std::string& file);

// How two images differ: the largest difference of one colour channel, and how many pixels
// differ by more than `tolerance` in some channel.
struct ImageDifference {
  bool same_size = false;
  int max_channel_difference = 0;
  std::int64_t pixels_over_tolerance = 0;
  double mean_channel_difference = 0;
};
ImageDifference compare_images(const Image& a, const Image& b, int tolerance);

}  // namespace fapc::face
