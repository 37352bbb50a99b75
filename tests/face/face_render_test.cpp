// Golden pictures of the face (reviewed as images; tolerance in face_test_support.hpp), and FAP
// motions measured on the rendered image.
#include <gtest/gtest.h>

#include <cmath>

#include "face/face_test_support.hpp"
#include "fapc/codec/fap_table.hpp"
#include "fapc/face/face_model.hpp"
#include "fapc/face/pictures.hpp"
#include "fapc/face/renderer.hpp"
#include "support/test_support.hpp"

namespace fapc::face {
namespace {

using test::constant_sequence;
using test::expect_golden_image;

Image render_values(std::initializer_list<std::pair<int, double>> values, int w = 320, int h = 240) {
  FapValues v{};
  for (const auto& [fap, value] : values) v[static_cast<std::size_t>(fap - 1)] = value;
  FaceRenderer renderer(w, h);
  return renderer.render(v);
}

TEST(FaceRender, Neutral) { expect_golden_image("golden/face/neutral.png", render_values({})); }

TEST(FaceRender, Blink) { expect_golden_image("golden/face/blink.png", render_values({{19, 1024}, {20, 1024}})); }

TEST(FaceRender, HeadTurn) {
  // 0.5 rad to the face's left, a little down and tilted right.
  expect_golden_image("golden/face/head-turn.png", render_values({{49, 50000}, {48, 10000}, {50, 8000}}));
}

TEST(FaceRender, OpenJawAtItsMaximum) {
  // Tall picture: the chin at open_jaw's legal maximum drops 4.2 mouth-nose separations.
  expect_golden_image("golden/face/open-jaw-max.png", render_values({{3, find_fap(3)->legal_max()}}, 240, 480));
}

// Every group of FAPs 2..10 at both ends of its legal range: a sheet of 18 cells, group 2 at
// +max then -max, group 3 at +max then -max...
TEST(FaceRender, EachGroupAtItsExtremes) {
  FapSequence s;
  s.fps = 25;
  for (int g = 2; g <= 10; ++g)
    for (int sign : {1, -1}) {
      FapFrame f;
      f.number = static_cast<std::int64_t>(s.frames.size());
      const FapGroup& group = fap_groups()[static_cast<std::size_t>(g - 1)];
      for (int fap = 3; fap <= kFapCount; ++fap)  // every FAP sent, so nothing is held from before
        f.set(fap, fap >= group.first_fap && fap <= group.last_fap ? sign * find_fap(fap)->legal_max() : 0);
      s.frames.push_back(f);
    }
  PictureOptions o;
  o.width = 200;
  o.height = 150;
  o.sheet = 18;
  Result<Image> sheet = render_picture(FaceTrack(s), o, "groups.png");
  ASSERT_TRUE(sheet) << sheet.error().message;
  expect_golden_image("golden/face/groups-at-extremes.png", *sheet);
}

// The lowest pixel of the chin's outline on the picture's centre column, scanning up from the
// bottom (below the chin there is only the neck).
int chin_edge_row(const Image& image, int column) {
  for (int y = image.height - 1; y >= 0; --y) {
    const std::uint32_t p = image.at(column, y);
    const int r = (p >> 16) & 0xff, g = (p >> 8) & 0xff, b = p & 0xff;
    if (std::abs(r - 168) < 40 && std::abs(g - 115) < 40 && std::abs(b - 89) < 40) return y;
  }
  return -1;
}

TEST(FaceRender, OpenJawMovesTheChinByValueTimesMnsOnTheImage) {
  const int value = find_fap(3)->legal_max();  // 4320
  FaceRenderer renderer(240, 480);
  const int column = static_cast<int>(std::lround(renderer.screen_x(0)));
  FapValues v{};
  const int rest = chin_edge_row(renderer.render(v), column);
  v[2] = value;
  const int open = chin_edge_row(renderer.render(v), column);
  ASSERT_GT(rest, 0);
  ASSERT_GT(open, rest);
  const double measured_mm = (open - rest) / renderer.scale();
  const double expected_mm = value * fapus().mns0 / 1024;  // 84.375 mm
  EXPECT_NEAR(measured_mm, expected_mm, 1.5 / renderer.scale()) << "in pixels: " << open - rest;
}

TEST(FaceRender, FaceFitsThePictureAtAnyHeadRotation) {
  // At the extremes of the rotation range, no face pixel reaches the picture's edge rows above
  // the neck: the framing radius holds every rotated point.
  const int max = find_fap(49)->legal_max();
  for (const auto& values :
       {std::pair{48, max}, std::pair{48, -max / 2}, std::pair{49, max / 2}, std::pair{50, max / 2}}) {
    const Image image = render_values({values}, 320, 240);
    const std::uint32_t background = image.at(0, 0);
    for (int x = 0; x < image.width; ++x) EXPECT_EQ(image.at(x, 0), background) << "top row, x " << x;
    for (int y = 0; y < image.height / 2; ++y) {
      EXPECT_EQ(image.at(0, y), background);
      EXPECT_EQ(image.at(image.width - 1, y), background);
    }
  }
}

TEST(FaceRender, BadPictureOptionsAreRefused) {
  const FaceTrack track(constant_sequence(3, 0));
  PictureOptions o;
  o.width = 8;
  EXPECT_EQ(render_picture(track, o, "x.png").error().kind, ErrorKind::usage);
  o = {};
  o.sheet = 401;
  EXPECT_EQ(render_picture(track, o, "x.png").error().kind, ErrorKind::limit_exceeded);
  o = {};
  o.frame = 2;
  o.time = 1;
  EXPECT_EQ(render_picture(track, o, "x.png").error().kind, ErrorKind::usage);
}

TEST(FaceRender, Figure3ProgramAsAContactSheet) {
  const std::string out = test::binary_dir() + "/face-figure3-sheet.png";
  const test::CommandRun run =
      test::run_fapc("render corpus/examples/mimic/figure3.mimic -o " + out + " --sheet 12 --size 320x240");
  ASSERT_EQ(run.exit_status, 0) << run.err;
  Result<Image> sheet = decode_png(test::read_text(out), out);
  ASSERT_TRUE(sheet);
  expect_golden_image("golden/face/figure3-sheet.png", *sheet);
}

}  // namespace
}  // namespace fapc::face
