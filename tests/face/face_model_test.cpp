// The neutral face's data and the FAP motions: checked against the standard's definitions, and
// the motion table against the FAP table's own "positive motion" column (two tables typed
// separately, so a slip in one shows up).
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "fapc/codec/fap_motion.hpp"
#include "fapc/codec/fap_table.hpp"
#include "fapc/face/face_model.hpp"

namespace fapc::face {
namespace {

TEST(FaceModel, FapusAreTheStandardDistancesOfTheNeutralFace) {
  // By hand from the point table: 3.1/3.3 at y = +-5.5; pupils at x = +-32; 3.5.y = 0 and
  // 9.15.y = -46; 9.15.y - 2.2.y = -46 - -66; 8.3/8.4 at x = +-25.
  EXPECT_DOUBLE_EQ(fapus().irisd0, 11);
  EXPECT_DOUBLE_EQ(fapus().es0, 64);
  EXPECT_DOUBLE_EQ(fapus().ens0, 46);
  EXPECT_DOUBLE_EQ(fapus().mns0, 20);
  EXPECT_DOUBLE_EQ(fapus().mw0, 50);
  EXPECT_DOUBLE_EQ(fapus().unit(Fapu::mns), 20.0 / 1024);
  EXPECT_DOUBLE_EQ(fapus().unit(Fapu::au), 1e-5);
}

TEST(FaceModel, EveryFeaturePointAFapMovesIsOnTheFace) {
  for (int fap = 3; fap <= kFapCount; ++fap) {
    const FapMotion* m = fap_motion(fap);
    ASSERT_NE(m, nullptr);
    EXPECT_EQ(m->number, fap);
    if (fap == 47) continue;  // tongue roll acts on 6.3/6.4, which the face does not model
    EXPECT_TRUE(point_by_label(m->feature_point).has_value()) << "FAP " << fap << ": " << m->feature_point;
  }
}

TEST(FaceModel, NeutralFaceIsSymmetricAndLipsAreClosed) {
  for (const FacePoint& p : face_points()) {
    if (p.neutral.x == 0) continue;
    bool mirrored = false;
    for (const FacePoint& q : face_points())
      if (q.neutral.x == -p.neutral.x && q.neutral.y == p.neutral.y && q.neutral.z == p.neutral.z) mirrored = true;
    EXPECT_TRUE(mirrored) << p.name;
  }
  EXPECT_EQ(neutral(P::lip_t_mid_i).y, neutral(P::lip_b_mid_i).y);
  EXPECT_EQ(neutral(P::lip_l_corner_i).y, neutral(P::lip_t_mid_i).y);  // a horizontal line
}

// The motion table's directions against the FAP table's words.
TEST(FapMotion, DirectionsAgreeWithThePositiveMotionColumn) {
  for (const FapInfo& info : fap_table()) {
    const FapMotion& m = *fap_motion(info.number);
    const std::string word(info.positive_motion);
    const int* d = m.direction;
    if (m.action == FapAction::translation) {
      if (word == "up")
        EXPECT_EQ(d[1], 1) << info.name;
      else if (word == "down")
        EXPECT_EQ(d[1], -1) << info.name;
      else if (word == "left")
        EXPECT_EQ(d[0], 1) << info.name;
      else if (word == "right")
        EXPECT_EQ(d[0], -1) << info.name;
      else if (word == "forward")
        EXPECT_EQ(d[2], 1) << info.name;
      else
        ADD_FAILURE() << info.name << ": " << word;
      EXPECT_EQ(std::abs(d[0]) + std::abs(d[1]) + std::abs(d[2]), 1) << info.name;
    } else if (m.action == FapAction::rotation) {
      EXPECT_EQ(info.unit, Fapu::au) << info.name;
    } else if (m.action == FapAction::dilation) {
      EXPECT_EQ(word, "growing");
    } else {
      EXPECT_LE(info.number, 2);
    }
  }
}

}  // namespace
}  // namespace fapc::face
