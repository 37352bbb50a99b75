// FAP values move the posed face's points as the standard says: value x FAPU along the FAP's
// direction; rotations turn the head and the eyes the way their names say.
#include <gtest/gtest.h>

#include <cmath>

#include "face/face_test_support.hpp"
#include "fapc/face/face_pose.hpp"
#include "fapc/face/face_track.hpp"

namespace fapc::face {
namespace {

FapValues with(std::initializer_list<std::pair<int, double>> values) {
  FapValues v{};
  for (const auto& [fap, value] : values) v[static_cast<std::size_t>(fap - 1)] = value;
  return v;
}

TEST(FacePose, OpenJawMovesTheChinDownByValueTimesMns) {
  const FacePose pose = pose_face(with({{3, 1000}}));
  EXPECT_NEAR(pose.at(P::chin_bottom).y, neutral(P::chin_bottom).y - 1000 * 20.0 / 1024, 1e-9);
  EXPECT_DOUBLE_EQ(pose.at(P::chin_bottom).x, neutral(P::chin_bottom).x);
  // The lower lip rides on the jaw; the upper lip stays.
  EXPECT_LT(pose.at(P::lip_b_mid_i).y, neutral(P::lip_b_mid_i).y - 19);
  EXPECT_DOUBLE_EQ(pose.at(P::lip_t_mid_i).y, neutral(P::lip_t_mid_i).y);
}

TEST(FacePose, EyelidsCloseAtOneIrisDiameterAndNeverCross) {
  const FacePose closed = pose_face(with({{19, 1024}}));
  EXPECT_NEAR(closed.at(P::lid_t_l).y, closed.at(P::lid_b_l).y, 1e-9);
  const FacePose past = pose_face(with({{19, 2000}}));
  EXPECT_GE(past.at(P::lid_t_l).y, past.at(P::lid_b_l).y);
  EXPECT_DOUBLE_EQ(past.at(P::lid_t_r).y, neutral(P::lid_t_r).y);  // the other eye stays open
}

TEST(FacePose, HeadYawLeftTurnsTheNoseToTheFacesLeft) {
  const FacePose pose = pose_face(with({{49, 30000}}));  // 0.3 rad
  EXPECT_GT(pose.at(P::nose_tip).x, 10);
  // The rotation keeps distances to 7.1.
  const Vec3 d0 = neutral(P::nose_tip) - neutral(P::spine_top);
  const Vec3 d1 = pose.at(P::nose_tip) - pose.at(P::spine_top);
  EXPECT_NEAR(d0.x * d0.x + d0.y * d0.y + d0.z * d0.z, d1.x * d1.x + d1.y * d1.y + d1.z * d1.z, 1e-6);
}

TEST(FacePose, HeadPitchDownLowersTheNoseAndRollRightTiltsTheTopRight) {
  EXPECT_LT(pose_face(with({{48, 20000}})).at(P::nose_tip).y, neutral(P::nose_tip).y);
  EXPECT_LT(pose_face(with({{50, 20000}})).at(P::head_top).x, -10);
}

TEST(FacePose, EyeballsTurnAndPupilsDilate) {
  const FacePose pose = pose_face(with({{23, 20000}, {25, 20000}, {29, 300}}));
  EXPECT_GT(pose.eyes[0].gaze.x, 0.1);   // left
  EXPECT_LT(pose.eyes[0].gaze.y, -0.1);  // down
  EXPECT_NEAR(pose.eyes[1].gaze.z, 1, 1e-12);
  EXPECT_NEAR(pose.eyes[0].pupil_radius, (11.0 / 3 + 300 * 11.0 / 1024) / 2, 1e-9);
}

TEST(FaceTrack, ValuesAreHeldAndVisemesBlendAsTheStreamSays) {
  FapSequence s;
  FapFrame a;
  a.number = 0;
  a.set(3, 100);
  FapFrame b;
  b.number = 4;
  b.mask.set(0);
  b.viseme = VisemeFields{10, 1, 21, 0};  // AA x 21/63 + PP x 42/63
  s.frames = {a, b};
  const FaceTrack track(s);
  EXPECT_EQ(track.frame_count(), 5);
  EXPECT_EQ(track.at_frame(3)[2], 100);  // held
  const double expected = 100 + 700 * 21.0 / 63 + 40 * 42.0 / 63;
  EXPECT_NEAR(track.at_frame(4)[2], expected, 1e-9);
  EXPECT_NEAR(track.at_time(4.0 / 25)[2], expected, 1e-9);
  EXPECT_EQ(track.at_frame(4)[0], 0);
}

TEST(FaceTrack, ExpressionsAddByTheirIntensities) {
  FapSequence s;
  FapFrame f;
  f.mask.set(1);
  f.expression = ExpressionFields{1, 63, 6, 0, 0, 0};  // joy at full, surprise at 0
  s.frames = {f};
  EXPECT_EQ(FaceTrack(s).at_frame(0)[11], expression_displacements(1)[11]);
}

}  // namespace
}  // namespace fapc::face
