// The pictures of the 3D head in docs/render.md ("The 3D head"), drawn by the reference rasteriser
// (reference_raster.cpp: its own projection and depth buffer, lit by the mesh's normals) and kept as
// golden images in corpus/golden/head3d/: the head from the front and three-quarters, the mouth
// open; its feature points; and how far each FAP's target moves the skin around its point (the
// influence weights at work). A change to the mesh or its bindings shows here as a picture to
// review (FAPC_REGENERATE_GOLDEN=1, then look at the images).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "face/face_test_support.hpp"
#include "fapc/face/face_model.hpp"
#include "fapc/face/image.hpp"
#include "fapc/head3d/head_mesh.hpp"
#include "fapc/head3d/head_morphs.hpp"
#include "reference_raster.hpp"

namespace fapc::head3d {
namespace {

constexpr int kPanelWidth = 300, kPanelHeight = 340;
constexpr std::uint32_t kBackground = 0xfff2f2f2u;

std::uint32_t rgb(double r, double g, double b) {
  auto channel = [](double c) {
    return static_cast<std::uint32_t>(std::lround(255 * std::pow(std::clamp(c, 0.0, 1.0), 1 / 2.2)));
  };
  return 0xff000000u | channel(r) << 16 | channel(g) << 8 | channel(b);
}

HeadFrame neutral_frame() {
  HeadFrame f;
  f.weights.assign(morph_targets().size(), 0.0);
  f.head = {0, 0, 0, 1};
  f.eyes[0] = f.eyes[1] = {0, 0, 0, 1};
  return f;
}

std::size_t target_of(int fap) {
  const auto& targets = morph_targets();
  const auto it = std::find_if(targets.begin(), targets.end(), [&](const MorphTarget& t) { return t.fap == fap; });
  EXPECT_NE(it, targets.end()) << "FAP " << fap << " has no target";
  return static_cast<std::size_t>(it - targets.begin());
}

// The head seen from `yaw_degrees` to the face's left of straight ahead, framed on the neutral
// head's middle, at a distance that fits its height.
reference::Camera camera_at(double yaw_degrees) {
  double low = 1e9, high = -1e9;
  for (const Vec3& p : head_mesh().positions) low = std::min(low, p.y), high = std::max(high, p.y);
  const double middle = (low + high) / 2 * 1e-3, distance = 0.62, yaw = yaw_degrees * M_PI / 180;
  reference::Camera c;
  c.aspect = double(kPanelWidth) / kPanelHeight;
  c.position = {distance * std::sin(yaw), middle, 0.03 + distance * std::cos(yaw)};
  c.target = {0, middle, 0.03};
  return c;
}

// Pixels coloured by material and light.
face::Image lit(const reference::MaterialImage& image) {
  face::Image out(image.width, image.height);
  for (std::size_t i = 0; i < out.pixels.size(); ++i) {
    const int m = image.material[i];
    if (m < 0) {
      out.pixels[i] = kBackground;
      continue;
    }
    const auto c = material_colour(static_cast<Material>(m));
    out.pixels[i] = rgb(c[0] * image.shade[i], c[1] * image.shade[i], c[2] * image.shade[i]);
  }
  return out;
}

// Grey skin, and where the surface moved from the other frame a colour from yellow (little) to
// dark red (the panel's most), so that the fall-off around a moved point shows.
face::Image moved(const reference::MaterialImage& image) {
  double most = 0;
  for (double m : image.motion) most = std::max(most, m);
  face::Image out(image.width, image.height);
  for (std::size_t i = 0; i < out.pixels.size(); ++i) {
    const double s = image.shade[i];
    if (image.material[i] < 0) {
      out.pixels[i] = kBackground;
      continue;
    }
    const double t = most > 0 ? image.motion[i] / most : 0;
    if (t < 0.01) {
      out.pixels[i] = rgb(0.55 * s, 0.55 * s, 0.55 * s);
      continue;
    }
    // yellow (1, 0.9, 0.2) at t = 0 to dark red (0.55, 0, 0) at t = 1
    out.pixels[i] = rgb(s * (1 - 0.45 * t), s * 0.9 * (1 - t), s * 0.2 * (1 - t));
  }
  return out;
}

face::Image side_by_side(const std::vector<face::Image>& panels) {
  face::Image out(kPanelWidth * static_cast<int>(panels.size()), kPanelHeight);
  for (std::size_t k = 0; k < panels.size(); ++k)
    for (int y = 0; y < kPanelHeight; ++y)
      for (int x = 0; x < kPanelWidth; ++x)
        out.pixels[static_cast<std::size_t>(y) * out.width + static_cast<int>(k) * kPanelWidth + x] =
            panels[k].at(x, y);
  return out;
}

void fill(face::Image& image, int x0, int y0, int w, int h, std::uint32_t colour) {
  for (int y = std::max(0, y0); y < std::min(image.height, y0 + h); ++y)
    for (int x = std::max(0, x0); x < std::min(image.width, x0 + w); ++x)
      image.pixels[static_cast<std::size_t>(y) * image.width + x] = colour;
}

// A label such as "8.10" in seven-segment digits of our own (no font, so the picture is the same
// on every machine): each character 3 units wide and 5 high, with a unit between characters; a
// unit is 2 pixels.
void label(face::Image& image, int x, int y, std::string_view text, std::uint32_t colour) {
  constexpr int u = 2;
  auto fill = [&](int x0, int y0, int w, int h, std::uint32_t c) { head3d::fill(image, x0, y0, w * u, h * u, c); };
  // Segments a b c d e f g as bits 0..6 (a top, b upper right, c lower right, d bottom, e lower
  // left, f upper left, g middle).
  static constexpr std::uint8_t kDigits[10] = {0x3f, 0x06, 0x5b, 0x4f, 0x66, 0x6d, 0x7d, 0x07, 0x7f, 0x6f};
  for (char ch : text) {
    if (ch == '.') {
      fill(x, y + 4 * u, 1, 1, colour);
      x += 2 * u;
      continue;
    }
    const std::uint8_t s = kDigits[ch - '0'];
    if (s & 0x01) fill(x, y, 3, 1, colour);
    if (s & 0x02) fill(x + 2 * u, y, 1, 3, colour);
    if (s & 0x04) fill(x + 2 * u, y + 2 * u, 1, 3, colour);
    if (s & 0x08) fill(x, y + 4 * u, 3, 1, colour);
    if (s & 0x10) fill(x, y + 2 * u, 1, 3, colour);
    if (s & 0x20) fill(x, y, 1, 3, colour);
    if (s & 0x40) fill(x, y + 2 * u, 3, 1, colour);
    x += 4 * u;
  }
}

TEST(HeadFigures, TheHeadFromTheFrontAndThreeQuartersAndWithTheMouthOpen) {
  const HeadFrame neutral = neutral_frame();
  HeadFrame open = neutral;
  open.weights[target_of(3)] = 700.0 / kTargetUnits;   // open_jaw
  open.weights[target_of(6)] = 150.0 / kTargetUnits;   // stretch_l_cornerlip
  open.weights[target_of(7)] = 150.0 / kTargetUnits;   // stretch_r_cornerlip
  open.weights[target_of(19)] = 900.0 / kTargetUnits;  // close_t_l_eyelid
  test::expect_golden_image(
      "golden/head3d/views.png",
      side_by_side({lit(reference::rasterise_frame(neutral, camera_at(0), kPanelWidth, kPanelHeight)),
                    lit(reference::rasterise_frame(neutral, camera_at(35), kPanelWidth, kPanelHeight)),
                    lit(reference::rasterise_frame(open, camera_at(20), kPanelWidth, kPanelHeight))}));
}

TEST(HeadFigures, TheFeaturePointsTheHeadIsBuiltOn) {
  constexpr int kScale = 3;  // a larger picture, so that the labels have room
  reference::Camera camera = camera_at(0);
  const int width = kPanelWidth * kScale, height = kPanelHeight * kScale;
  const reference::MaterialImage image = reference::rasterise_frame(neutral_frame(), camera, width, height);
  face::Image out = lit(image);
  const HeadMesh& mesh = head_mesh();
  int shown = 0;
  for (const face::FacePoint& point : face::face_points()) {
    const int v = mesh.feature_vertex[static_cast<std::size_t>(point.id)];
    if (point.label.empty() || v < 0) continue;
    const Vec3 p = mesh.positions[static_cast<std::size_t>(v)];
    const auto at = reference::project_point(camera, width, height, {p.x * 1e-3, p.y * 1e-3, p.z * 1e-3});
    const int x = static_cast<int>(at[0]), y = static_cast<int>(at[1]);
    if (x < 0 || y < 0 || x >= width || y >= height) continue;
    // Only the points the picture shows: those at the surface drawn at their pixel (not behind
    // the lips, inside the mouth or on the far side).
    if (at[2] < image.inverse_depth[static_cast<std::size_t>(y) * width + x] * 0.995) continue;
    fill(out, x - 2, y - 2, 5, 5, 0xffd01010u);
    label(out, x + 4, y - 11, point.label, 0xff202020u);
    ++shown;
  }
  EXPECT_GE(shown, 40) << "the front view should show most of the face's feature points";
  test::expect_golden_image("golden/head3d/feature-points.png", out);
}

TEST(HeadFigures, EachFapMovesTheSkinAroundItsPoint) {
  const HeadFrame neutral = neutral_frame();
  std::vector<face::Image> panels;
  // open_jaw, raise_l_i_eyebrow, close_t_l_eyelid, stretch_l_cornerlip, puff_l_cheek
  for (int fap : {3, 31, 19, 6, 39}) {
    // At a weight that moves the FAP's own point by 8 mm, about as far as faces go.
    const MorphTarget& target = morph_targets()[target_of(fap)];
    double largest = 0;
    for (const Vec3& d : target.displacements)
      largest = std::max(largest, std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z));
    HeadFrame f = neutral;
    f.weights[target_of(fap)] = 8 / largest;
    const reference::MaterialImage image =
        reference::rasterise_frame(f, camera_at(fap == 3 ? 40 : 25), kPanelWidth, kPanelHeight, &neutral);
    double most = 0;
    for (double m : image.motion) most = std::max(most, m);
    EXPECT_GT(most, 1.0) << "FAP " << fap << "'s target moves the visible skin by more than a millimetre";
    panels.push_back(moved(image));
  }
  test::expect_golden_image("golden/head3d/influence.png", side_by_side(panels));
}

}  // namespace
}  // namespace fapc::head3d
