// Each standard faceLexeme moves what its name says on the face fapc draws: a document with the
// lexeme alone is compiled, the frame at its hold is posed (fapc::face::pose_face, the points the
// renderer draws), and the named points are measured against the neutral face. Face coordinates:
// x towards the character's left, y up (fapc/codec/fap_motion.hpp).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "fapc/face/face_pose.hpp"
#include "fapc/face/face_track.hpp"
#include "fapc/pipeline/registry.hpp"
#include "support/test_support.hpp"

namespace fapc {
namespace {

namespace fs = std::filesystem;
using face::P;

constexpr double kMoved = 0.3;  // millimetres: well above rounding, well below any lexeme's motion

face::FacePose pose_of(const std::string& lexeme) {
  const fs::path dir = test::scratch_folder("bml-lexeme");
  const fs::path path = dir / (lexeme + ".bml");
  std::ofstream(path)
      << "<bml xmlns=\"http://www.bml-initiative.org/bml/bml-1.0\" id=\"b\"><faceLexeme id=\"f\" lexeme=\"" << lexeme
      << "\" start=\"0\"/></bml>\n";
  pipeline::ConvertOptions options;
  options.fps = 25;
  Result<pipeline::Loaded> loaded = pipeline::load(path.string(), options);
  EXPECT_TRUE(loaded) << (loaded ? "" : loaded.error().message);
  face::FapValues values{};
  if (loaded && loaded->frames.frames.size() > 25) {
    const FapFrame& held = loaded->frames.frames[25];  // 1 s: between attackPeak (0.4) and relax (1.6)
    for (int fap = 3; fap <= kFapCount; ++fap)
      if (held.has(fap)) values[static_cast<std::size_t>(fap - 1)] = held.value(fap);
  } else {
    ADD_FAILURE() << lexeme << ": too few frames";
  }
  return face::pose_face(values);
}

const face::FacePose& neutral() {
  static const face::FacePose pose = face::pose_face(face::FapValues{});
  return pose;
}

double dy(const face::FacePose& pose, P p) { return pose.at(p).y - neutral().at(p).y; }
double dx(const face::FacePose& pose, P p) { return pose.at(p).x - neutral().at(p).x; }

// A one-sided lexeme moves `moved` up (direction +1) or down (-1) and leaves its mirror `still`.
void expect_one_side(const std::string& lexeme, P moved, P still, int direction) {
  SCOPED_TRACE(lexeme);
  const auto pose = pose_of(lexeme);
  EXPECT_GT(direction * dy(pose, moved), kMoved);
  EXPECT_NEAR(dy(pose, still), 0, 1e-9);
}

TEST(BmlLexemeFace, RaiseBrowsLiftsBothBrows) {
  const auto pose = pose_of("RAISE_BROWS");
  for (P p : {P::brow_l_inner, P::brow_r_inner, P::brow_l_outer, P::brow_r_outer}) EXPECT_GT(dy(pose, p), kMoved);
}

TEST(BmlLexemeFace, RaiseLeftBrowLiftsTheLeftOnly) {
  expect_one_side("RAISE_LEFT_BROW", P::brow_l_mid, P::brow_r_mid, 1);
}

TEST(BmlLexemeFace, RaiseRightBrowLiftsTheRightOnly) {
  expect_one_side("RAISE_RIGHT_BROW", P::brow_r_mid, P::brow_l_mid, 1);
}

TEST(BmlLexemeFace, LowerBrowsBringsThemDownAndTogether) {
  const auto pose = pose_of("LOWER_BROWS");
  EXPECT_LT(dy(pose, P::brow_l_inner), -kMoved);
  EXPECT_LT(dy(pose, P::brow_r_inner), -kMoved);
  // Together: the inner ends come closer (the left one moves right, to -x).
  EXPECT_LT(dx(pose, P::brow_l_inner) - dx(pose, P::brow_r_inner), 0);
}

TEST(BmlLexemeFace, LowerLeftBrowLowersTheLeftOnly) {
  expect_one_side("LOWER_LEFT_BROW", P::brow_l_inner, P::brow_r_inner, -1);
}

TEST(BmlLexemeFace, LowerRightBrowLowersTheRightOnly) {
  expect_one_side("LOWER_RIGHT_BROW", P::brow_r_inner, P::brow_l_inner, -1);
}

TEST(BmlLexemeFace, ObliqueBrowsRaiseTheInnerEndsAboveTheOuter) {
  const auto pose = pose_of("OBLIQUE_BROWS");
  EXPECT_GT(dy(pose, P::brow_l_inner), kMoved);
  EXPECT_GT(dy(pose, P::brow_l_inner) - dy(pose, P::brow_l_outer), kMoved);
  EXPECT_GT(dy(pose, P::brow_r_inner) - dy(pose, P::brow_r_outer), kMoved);
}

TEST(BmlLexemeFace, LowerMouthCornersPullsBothCornersDown) {
  const auto pose = pose_of("LOWER_MOUTH_CORNERS");
  EXPECT_LT(dy(pose, P::lip_l_corner_o), -kMoved);
  EXPECT_LT(dy(pose, P::lip_r_corner_o), -kMoved);
}

TEST(BmlLexemeFace, LowerLeftMouthCornerPullsTheLeftDownOnly) {
  expect_one_side("LOWER_LEFT_MOUTH_CORNER", P::lip_l_corner_o, P::lip_r_corner_o, -1);
}

TEST(BmlLexemeFace, LowerRightMouthCornerPullsTheRightDownOnly) {
  expect_one_side("LOWER_RIGHT_MOUTH_CORNER", P::lip_r_corner_o, P::lip_l_corner_o, -1);
}

TEST(BmlLexemeFace, RaiseMouthCornersLiftsBothCorners) {
  const auto pose = pose_of("RAISE_MOUTH_CORNERS");
  EXPECT_GT(dy(pose, P::lip_l_corner_o), kMoved);
  EXPECT_GT(dy(pose, P::lip_r_corner_o), kMoved);
}

TEST(BmlLexemeFace, RaiseLeftMouthCornerLiftsTheLeftOnly) {
  expect_one_side("RAISE_LEFT_MOUTH_CORNER", P::lip_l_corner_o, P::lip_r_corner_o, 1);
}

TEST(BmlLexemeFace, RaiseRightMouthCornerLiftsTheRightOnly) {
  expect_one_side("RAISE_RIGHT_MOUTH_CORNER", P::lip_r_corner_o, P::lip_l_corner_o, 1);
}

TEST(BmlLexemeFace, OpenMouthDropsTheJawAndPartsTheLips) {
  const auto pose = pose_of("OPEN_MOUTH");
  EXPECT_LT(dy(pose, P::chin_bottom), -kMoved);
  const double gap = pose.at(P::lip_t_mid_i).y - pose.at(P::lip_b_mid_i).y;
  const double gap0 = neutral().at(P::lip_t_mid_i).y - neutral().at(P::lip_b_mid_i).y;
  EXPECT_GT(gap - gap0, kMoved);
}

TEST(BmlLexemeFace, OpenLipsPartsTheLipsWithoutTheJaw) {
  const auto pose = pose_of("OPEN_LIPS");
  EXPECT_NEAR(dy(pose, P::chin_bottom), 0, 1e-9);
  EXPECT_GT(dy(pose, P::lip_t_mid_i) - dy(pose, P::lip_b_mid_i), kMoved);
}

TEST(BmlLexemeFace, WidenEyesLiftsTheUpperLids) {
  const auto pose = pose_of("WIDEN_EYES");
  EXPECT_GT(dy(pose, P::lid_t_l), kMoved);
  EXPECT_GT(dy(pose, P::lid_t_r), kMoved);
}

TEST(BmlLexemeFace, CloseEyesBringsTheUpperLidsDownToTheLower) {
  const auto pose = pose_of("CLOSE_EYES");
  for (auto [top, bottom] : {std::pair{P::lid_t_l, P::lid_b_l}, std::pair{P::lid_t_r, P::lid_b_r}}) {
    const double open = neutral().at(top).y - neutral().at(bottom).y;
    const double now = pose.at(top).y - pose.at(bottom).y;
    EXPECT_LT(now, 0.2 * open) << "the eye should be nearly shut";
  }
}

}  // namespace
}  // namespace fapc
