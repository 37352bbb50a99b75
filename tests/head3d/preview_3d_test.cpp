// The preview page's 3D view in headless Chromium (WebGL through its software renderer): the page
// seeks to a frame, the 3D canvas is captured, and what it shows is compared with the same frame
// drawn by a second implementation (reference_raster.cpp: fapc::head3d's mesh, its own projection
// and depth buffer). Compared are shapes, not colours (three.js shades with its lights, the
// reference draws material ids): the head's silhouette, and which pixels change between the
// neutral frame and a frame with the jaw open.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>

#include "fapc/codec/fap_file.hpp"
#include "fapc/face/image.hpp"
#include "fapc/face/preview_page.hpp"
#include "fapc/head3d/head_mesh.hpp"
#include "reference_raster.hpp"
#include "support/test_support.hpp"

namespace fapc::head3d {
namespace {

constexpr int kWidth = 320, kHeight = 240, kFps = 25;
// The page's 3D background (preview_page_3d.cpp: renderer.setClearColor(0x46505a)).
constexpr int kBackground[3] = {0x46, 0x50, 0x5a};

// Frame 0 neutral; 1 the jaw open and the eyes closed; 2 the same with the head turned to the
// face's left and tilted, the eyes turned.
FapSequence three_frames() {
  FapSequence s;
  s.fps = kFps;
  const std::vector<std::vector<std::pair<int, int>>> values = {
      {},
      {{3, 700}, {19, 1024}, {20, 1024}},
      {{3, 700}, {19, 1024}, {20, 1024}, {49, 35000}, {48, 8000}, {50, -10000}, {23, 20000}, {24, 20000}}};
  for (std::size_t k = 0; k < values.size(); ++k) {
    FapFrame f;
    f.number = static_cast<std::int64_t>(k);
    for (int fap : {3, 19, 20, 23, 24, 48, 49, 50}) f.set(fap, 0);  // every frame says all it moves
    for (const auto& [fap, value] : values[k]) f.set(fap, value);
    s.frames.push_back(f);
  }
  return s;
}

struct Shot {
  face::Image image;
  reference::Camera camera;
};

std::string page_path() {
  static const std::string page = [] {
    const std::string dir = test::binary_dir() + "/head3d-page";
    std::filesystem::create_directories(dir);
    std::ofstream(dir + "/three.fap") << write_fap_text(three_frames());
    const test::CommandRun run =
        test::run_fapc("render " + dir + "/three.fap -o " + dir + "/three.html --view both --size " +
                       std::to_string(kWidth) + "x" + std::to_string(kHeight));
    EXPECT_EQ(run.exit_status, 0) << run.err;
    return dir + "/three.html";
  }();
  return page;
}

// The 3D canvas once the page has shown frame k (seeking into the frame's middle).
Shot take_screenshot(int frame) {
  const std::string out = test::binary_dir() + "/head3d-page/shot" + std::to_string(frame) + ".png";
  face::PreviewOptions layout;
  layout.width = kWidth;
  layout.view = face::PreviewView::both;
  const test::CommandRun run = test::run_shell(
      "python3 " + test::source_dir() + "/tests/face/browser_screenshot.py chromium 'file://" + page_path() +
      "#t=" + std::to_string((frame + 0.5) / kFps) + "' " + out + " " + std::to_string(face::head3d_left(layout)) +
      " 0 " + std::to_string(kWidth) + " " + std::to_string(kHeight));
  Shot shot;
  EXPECT_EQ(run.exit_status, 0) << run.err << run.out;
  if (run.exit_status != 0) return shot;
  const auto state = nlohmann::json::parse(run.out);
  EXPECT_FALSE(state["data"].contains("head3dError")) << state.dump();
  const auto camera = nlohmann::json::parse(state["data"]["camera3d"].get<std::string>());
  shot.camera.fov_degrees = camera["fov"];
  shot.camera.aspect = camera["aspect"];
  for (int i = 0; i < 3; ++i) {
    shot.camera.position[static_cast<std::size_t>(i)] = camera["position"][i];
    shot.camera.target[static_cast<std::size_t>(i)] = camera["target"][i];
  }
  Result<face::Image> image = face::decode_png(test::read_text(out), out);
  EXPECT_TRUE(image);
  if (image) shot.image = *image;
  return shot;
}

// Each frame's shot is taken once for both tests (Chromium takes seconds to start).
const Shot& screenshot(int frame) {
  static std::map<int, Shot> shots;
  auto it = shots.find(frame);
  if (it == shots.end()) it = shots.emplace(frame, take_screenshot(frame)).first;
  return it->second;
}

int channel(std::uint32_t pixel, int c) { return static_cast<int>((pixel >> (16 - 8 * c)) & 0xff); }

bool is_background(std::uint32_t pixel) {
  for (int c = 0; c < 3; ++c)
    if (std::abs(channel(pixel, c) - kBackground[c]) > 10) return false;
  return true;
}

bool differs(std::uint32_t a, std::uint32_t b) {
  for (int c = 0; c < 3; ++c)
    if (std::abs(channel(a, c) - channel(b, c)) > 24) return true;
  return false;
}

// Intersection over union of two masks.
double overlap(const std::vector<bool>& a, const std::vector<bool>& b) {
  std::size_t both = 0, either = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    both += a[i] && b[i];
    either += a[i] || b[i];
  }
  return either ? double(both) / double(either) : 1.0;
}

std::vector<bool> silhouette(const face::Image& image) {
  std::vector<bool> mask;
  for (std::uint32_t p : image.pixels) mask.push_back(!is_background(p));
  return mask;
}

std::vector<bool> silhouette(const reference::MaterialImage& image) {
  std::vector<bool> mask;
  for (int m : image.material) mask.push_back(m >= 0);
  return mask;
}

// Frame k drawn by the reference, with each pixel's motion to frame `other` (none: -1).
reference::MaterialImage reference(int frame, const reference::Camera& camera, int other = -1) {
  const std::vector<HeadFrame> frames = head_frames(three_frames());
  return reference::rasterise_frame(frames[static_cast<std::size_t>(frame)], camera, kWidth, kHeight,
                                    other >= 0 ? &frames[static_cast<std::size_t>(other)] : nullptr);
}

// Tolerances: the page antialiases its edges and the reference does not, so a silhouette's border
// pixels may disagree (about 3% of the head's area at this size); a wrong pose or frame moves far
// more (the turned head against the upright one overlaps by about 0.8).
constexpr double kSilhouetteOverlap = 0.95;

TEST(Preview3d, ChromiumDrawsTheHeadWhereTheReferenceRasteriserDoes) {
  for (int frame : {0, 1, 2}) {
    SCOPED_TRACE("frame " + std::to_string(frame));
    const Shot& shot = screenshot(frame);
    ASSERT_EQ(shot.image.width, kWidth);
    const std::vector<bool> seen = silhouette(shot.image);
    const double right = overlap(seen, silhouette(reference(frame, shot.camera)));
    EXPECT_GE(right, kSilhouetteOverlap);
    // The comparison can tell frames apart: against the other pose it falls clearly.
    const double wrong = overlap(seen, silhouette(reference(frame == 2 ? 0 : 2, shot.camera)));
    EXPECT_LT(wrong, right - 0.05) << "right " << right << " wrong " << wrong;
  }
}

// Every pixel within `reach` pixels of a pixel of the mask.
std::vector<bool> grown(const std::vector<bool>& mask, int reach) {
  std::vector<bool> out(mask.size(), false);
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      if (!mask[static_cast<std::size_t>(y) * kWidth + x]) continue;
      for (int dy = -reach; dy <= reach; ++dy)
        for (int dx = -reach; dx <= reach; ++dx)
          if (x + dx >= 0 && x + dx < kWidth && y + dy >= 0 && y + dy < kHeight)
            out[static_cast<std::size_t>(y + dy) * kWidth + x + dx] = true;
    }
  return out;
}

// The share of the pixels of `a` that lie within `reach` pixels of a pixel of `b`.
double share_near(const std::vector<bool>& a, const std::vector<bool>& b, int reach) {
  const std::vector<bool> near = grown(b, reach);
  std::size_t count = 0, close = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    count += a[i];
    close += a[i] && near[i];
  }
  return count ? double(close) / double(count) : 1.0;
}

TEST(Preview3d, OpeningTheJawChangesTheMouthWhereTheReferenceSaysAndNothingElse) {
  const Shot& neutral = screenshot(0);
  const Shot& open = screenshot(1);
  ASSERT_EQ(neutral.image.width, kWidth);
  ASSERT_EQ(open.image.width, kWidth);
  const reference::MaterialImage before = reference(0, neutral.camera, 1), after = reference(1, neutral.camera, 0);
  // Seen: the pixels whose colour changed. Drawn: the pixels where another material shows (the
  // mouth opening, the lids over the eyes). Moving: the pixels that show, in either frame, a
  // surface that moves between the two; shading makes a moving surface change colour too, so a
  // change seen must lie there, while a change drawn must be seen.
  std::vector<bool> seen_change, drawn_change, moving, drawn_head;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * kWidth + x;
      seen_change.push_back(differs(neutral.image.pixels[i], open.image.pixels[i]));
      drawn_change.push_back(before.at(x, y) != after.at(x, y));
      moving.push_back(before.motion[i] > 0.1 || after.motion[i] > 0.1);
      drawn_head.push_back(before.at(x, y) >= 0 || after.at(x, y) >= 0);
    }
  std::size_t changed = 0, drawn = 0;
  for (std::size_t i = 0; i < seen_change.size(); ++i) changed += seen_change[i], drawn += drawn_change[i];
  // The jaw drops and the lids close: hundreds of pixels change at this size.
  EXPECT_GT(changed, 400u);
  EXPECT_GT(drawn, 400u);
  // Antialiased edges move a pixel or two: within 2 pixels, every material change the reference
  // draws is seen (nearly: 90%), and every change seen is on a moving surface (99%).
  EXPECT_GE(share_near(drawn_change, seen_change, 2), 0.9);
  EXPECT_GE(share_near(seen_change, moving, 2), 0.99);
  // The background (2 pixels away from the head of either frame) stays as it was.
  EXPECT_EQ(share_near(seen_change, drawn_head, 2), 1.0);
}

// Mimic Figure 3 in the page's 3D view: at 10 s three.js holds the head turned and the left eye
// 0.8 closed, the same rotations and weights as the tests' own importer reads from the .glb.
TEST(Preview3d, Figure3TurnsTheHeadAndClosesTheEyeWhereTheProgramSays) {
  const std::string dir = test::binary_dir() + "/head3d-page";
  std::filesystem::create_directories(dir);
  const std::string page = dir + "/figure3.html", glb = dir + "/figure3.glb";
  ASSERT_EQ(
      test::run_fapc("render corpus/examples/mimic/figure3.mimic -o " + page + " --view 3d --size 160x120").exit_status,
      0);
  ASSERT_EQ(test::run_fapc("compile corpus/examples/mimic/figure3.mimic -o " + glb).exit_status, 0);
  const test::CommandRun shot =
      test::run_shell("python3 " + test::source_dir() + "/tests/face/browser_screenshot.py chromium 'file://" + page +
                      "#t=10.02' " + dir + "/figure3.png 0 0 160 120 'fapcHead3d.pose()'");
  ASSERT_EQ(shot.exit_status, 0) << shot.err << shot.out;
  const auto seen = nlohmann::json::parse(shot.out)["value"];
  const test::CommandRun read =
      test::run_shell("python3 " + test::source_dir() + "/tests/head3d/gltf_pose.py " + glb + " --time 10");
  ASSERT_EQ(read.exit_status, 0) << read.err;
  const auto file = nlohmann::json::parse(read.out);
  for (const std::string node : {"head", "eye_l", "eye_r"}) {
    double dot = 0;  // q and -q are the same rotation
    for (int i = 0; i < 4; ++i) dot += seen[node][i].get<double>() * file["rotations"][node][i].get<double>();
    EXPECT_NEAR(std::abs(dot), 1.0, 1e-5) << node;
  }
  EXPECT_LT(std::abs(seen["head"][3].get<double>()), 0.99);                   // turned
  EXPECT_NEAR(seen["weights"]["close_t_l_eyelid"].get<double>(), 0.8, 1e-3);  // 0.8 closed (819 / 1024)
  ASSERT_EQ(seen["weights"].size(), file["weights"].size());
  for (const auto& [name, weight] : file["weights"].items())
    EXPECT_NEAR(seen["weights"][name].get<double>(), weight.get<double>(), 1e-5) << name;
}

}  // namespace
}  // namespace fapc::head3d
