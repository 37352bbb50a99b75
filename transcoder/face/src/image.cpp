// PNG through cairo's own encoder and decoder (no other image library), and pixel comparison.
#include "fapc/face/image.hpp"

#include <cairo.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>

#include "fapc/face/codes.hpp"

namespace fapc::face {

namespace {

cairo_status_t append(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

struct Reader {
  std::string_view bytes;
  std::size_t at = 0;
};

cairo_status_t take(void* closure, unsigned char* data, unsigned int length) {
  auto* r = static_cast<Reader*>(closure);
  if (r->bytes.size() - r->at < length) return CAIRO_STATUS_READ_ERROR;
  std::memcpy(data, r->bytes.data() + r->at, length);
  r->at += length;
  return CAIRO_STATUS_SUCCESS;
}

}  // namespace

Result<std::string> encode_png(const Image& image) {
  // cairo writes from its own surface; wrap the pixels without copying (stride = width x 4).
  cairo_surface_t* surface = cairo_image_surface_create_for_data(
      reinterpret_cast<unsigned char*>(const_cast<std::uint32_t*>(image.pixels.data())), CAIRO_FORMAT_RGB24,
      image.width, image.height, image.width * 4);
  std::string out;
  const cairo_status_t status = cairo_surface_write_to_png_stream(surface, append, &out);
  cairo_surface_destroy(surface);
  if (status != CAIRO_STATUS_SUCCESS)
    return make_error(codes::picture::encode_failed, Location{},
                      std::string("cannot encode PNG: ") + cairo_status_to_string(status));
  return out;
}

Result<Image> decode_png(std::string_view bytes, const std::string& file) {
  Reader reader{bytes};
  cairo_surface_t* surface = cairo_image_surface_create_from_png_stream(take, &reader);
  if (cairo_surface_status(surface) != CAIRO_STATUS_SUCCESS) {
    cairo_surface_destroy(surface);
    return make_error(codes::picture::not_png, Location::whole_file(file), "not a PNG image cairo can read");
  }
  Image image(cairo_image_surface_get_width(surface), cairo_image_surface_get_height(surface));
  const int stride = cairo_image_surface_get_stride(surface);
  const unsigned char* data = cairo_image_surface_get_data(surface);
  const bool opaque = cairo_image_surface_get_format(surface) == CAIRO_FORMAT_RGB24;
  for (int y = 0; y < image.height; ++y) {
    const auto* row = reinterpret_cast<const std::uint32_t*>(data + static_cast<std::ptrdiff_t>(y) * stride);
    for (int x = 0; x < image.width; ++x)
      image.pixels[static_cast<std::size_t>(y) * image.width + x] = opaque ? (row[x] | 0xff000000u) : row[x];
  }
  cairo_surface_destroy(surface);
  return image;
}

ImageDifference compare_images(const Image& a, const Image& b, int tolerance) {
  ImageDifference d;
  d.same_size = a.width == b.width && a.height == b.height;
  if (!d.same_size) return d;
  std::int64_t total = 0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) {
    int worst = 0;
    for (int shift : {0, 8, 16}) {
      const int diff = std::abs(int((a.pixels[i] >> shift) & 0xff) - int((b.pixels[i] >> shift) & 0xff));
      worst = std::max(worst, diff);
      total += diff;
    }
    d.max_channel_difference = std::max(d.max_channel_difference, worst);
    if (worst > tolerance) ++d.pixels_over_tolerance;
  }
  d.mean_channel_difference = a.pixels.empty() ? 0 : double(total) / (3.0 * double(a.pixels.size()));
  return d;
}

}  // namespace fapc::face
