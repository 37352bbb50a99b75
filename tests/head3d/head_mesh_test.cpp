// The 3D head as data: a closed surface of a few thousand vertices through the feature points, and
// its morph targets doing what the 2D face does (the jaw-opening and blink measurements of
// tests/face hold on the mesh).
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "fapc/face/face_pose.hpp"
#include "fapc/head3d/head_mesh.hpp"
#include "fapc/head3d/head_morphs.hpp"

namespace fapc::head3d {
namespace {

using face::P;

double distance(Vec3 a, Vec3 b) {
  return std::sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) + (a.z - b.z) * (a.z - b.z));
}
int vertex_of(P p) { return head_mesh().feature_vertex[static_cast<std::size_t>(p)]; }

std::vector<double> weights_for(std::initializer_list<std::pair<int, double>> values) {
  FapSequence seq;
  FapFrame frame;
  for (const auto& [fap, value] : values) frame.set(fap, static_cast<std::int32_t>(value));
  seq.frames.push_back(frame);
  return head_frames(seq).at(0).weights;
}

TEST(HeadMesh, IsAFewThousandVerticesWithEveryPartClosed) {
  const HeadMesh& mesh = head_mesh();
  EXPECT_GT(mesh.positions.size(), 3000u);
  EXPECT_LT(mesh.positions.size(), 12000u);  // and indices fit glTF's unsigned short
  ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
  // Every edge of the whole mesh is used once in each direction: closed and consistently turned.
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
  for (const Part& part : mesh.parts)
    for (std::size_t i = 0; i < part.triangles.size(); i += 3)
      for (int k = 0; k < 3; ++k) ++edges[{part.triangles[i + k], part.triangles[i + (k + 1) % 3]}];
  int open = 0;
  for (const auto& [edge, count] : edges)
    if (count != 1 || edges.count({edge.second, edge.first}) == 0 || edges.at({edge.second, edge.first}) != 1) ++open;
  EXPECT_EQ(open, 0);
}

TEST(HeadMesh, PassesThroughTheFeaturePoints) {
  // The skin's interpolation is exact at the points it is built from; the lids lie 1.3 mm outside
  // the eyeball (kLidRadius); the rows are 3 mm apart, so the nearest vertex is within 2.5 mm.
  for (P p : {P::chin_bottom, P::chin_boss, P::lip_t_mid_o, P::lip_b_mid_o, P::lip_l_corner_o, P::nose_tip,
              P::brow_l_mid, P::brow_r_inner, P::cheek_l, P::hairline, P::lid_t_l, P::lid_b_r})
    EXPECT_LT(distance(head_mesh().positions[static_cast<std::size_t>(vertex_of(p))], face::neutral(p)), 2.5)
        << static_cast<int>(p);
}

// FaceRender.OpenJawMovesTheChinByValueTimesMnsOnTheImage on the mesh: open_jaw = 4320 moves the
// chin down by 4320 x MNS0/1024 = 84.375 mm, and the lower lip with it; the upper lip stays.
TEST(HeadMorphs, OpenJawMovesTheChinByValueTimesMns) {
  const std::vector<Vec3> p = morphed_positions(weights_for({{3, 4320}}));
  const Vec3 rest = head_mesh().positions[static_cast<std::size_t>(vertex_of(P::chin_bottom))];
  const Vec3 open = p[static_cast<std::size_t>(vertex_of(P::chin_bottom))];
  EXPECT_NEAR(rest.y - open.y, 4320 * face::fapus().mns0 / 1024, 1e-3);
  const auto lower = static_cast<std::size_t>(vertex_of(P::lip_b_mid_i)),
             upper = static_cast<std::size_t>(vertex_of(P::lip_t_mid_i));
  EXPECT_NEAR(head_mesh().positions[lower].y - p[lower].y, 84.375, 0.5);
  EXPECT_NEAR(p[upper].y, head_mesh().positions[upper].y, 1e-9);
  // The lips part: the inner lips, one vertex each at rest, are 84 mm apart.
  EXPECT_NEAR(distance(head_mesh().positions[lower], head_mesh().positions[upper]), 0, 1e-9);
  EXPECT_GT(p[upper].y - p[lower].y, 80);
}

// The blink of tests/face (close_t_l_eyelid = 1024: the top lid meets the bottom one) on the
// mesh: the lid's middle vertex reaches the bottom lid's, the other eye stays open, and every lid
// vertex stays outside the eyeball.
TEST(HeadMorphs, ABlinkClosesTheLidOverTheEyeball) {
  const std::vector<Vec3> p = morphed_positions(weights_for({{19, 1024}}));
  const auto top = static_cast<std::size_t>(vertex_of(P::lid_t_l)),
             bottom = static_cast<std::size_t>(vertex_of(P::lid_b_l));
  EXPECT_NEAR(p[top].y, p[bottom].y, 0.5);  // the middle vertex is the column nearest the middle
  EXPECT_GT(head_mesh().positions[top].y - head_mesh().positions[bottom].y, 10);
  const auto other = static_cast<std::size_t>(vertex_of(P::lid_t_r));
  EXPECT_DOUBLE_EQ(p[other].y, head_mesh().positions[other].y);
  for (const auto& [v, eye] : head_mesh().lid_vertices)
    EXPECT_GE(distance(p[v], eyeball_centre(eye)), face::kEyeballRadius) << v;
}

// A FAP's target moves its own feature point's vertex as fapc::face moves the point.
TEST(HeadMorphs, EveryFapTargetMovesItsPointByValueTimesFapu) {
  for (const MorphTarget& t : morph_targets()) {
    if (t.fap == 0) continue;
    const face::PointMotion own = face::point_motions(t.fap).front();
    const int v = vertex_of(own.point);
    if (v < 0) continue;
    std::vector<double> w(morph_targets().size());
    w[static_cast<std::size_t>(&t - morph_targets().data())] = 1;
    const Vec3 moved =
        morphed_positions(w)[static_cast<std::size_t>(v)] - head_mesh().positions[static_cast<std::size_t>(v)];
    const Vec3 expected = kTargetUnits * own.mm_per_unit;
    const bool lid =
        own.point == P::lid_t_l || own.point == P::lid_t_r || own.point == P::lid_b_l || own.point == P::lid_b_r;
    // Lids also move forward, over the eyeball; compare along the FAP's direction for them.
    if (lid)
      EXPECT_NEAR(moved.y, expected.y, 0.05 * std::abs(expected.y) + 0.05) << t.name;
    else
      EXPECT_LT(distance(moved, expected), 0.05 * distance(expected, {}) + 0.05) << t.name;
  }
}

// Visemes and expressions are their displacement sets: the viseme's target is the sum of its FAPs'.
TEST(HeadMorphs, AVisemeIsItsDisplacementSet) {
  FapSequence seq;
  FapFrame frame;
  frame.mask.set(0);
  frame.viseme.select1 = 10;  // AA
  frame.viseme.select2 = 10;
  frame.viseme.blend = 63;
  seq.frames.push_back(frame);
  const std::vector<Vec3> by_viseme = morphed_positions(head_frames(seq).at(0).weights);
  std::vector<std::pair<int, double>> set;
  const auto& aa = face::viseme_displacements(10);
  const std::vector<Vec3> by_faps =
      morphed_positions(weights_for({{3, aa[2]}, {4, aa[3]}, {5, aa[4]}, {51, aa[50]}, {52, aa[51]}}));
  for (std::size_t v = 0; v < by_faps.size(); ++v)
    ASSERT_LT(distance(by_viseme[v], by_faps[v]), 0.01) << v;  // targets leave out moves under 1e-3 mm
  EXPECT_GT(distance(by_viseme[static_cast<std::size_t>(vertex_of(P::chin_bottom))],
                     head_mesh().positions[static_cast<std::size_t>(vertex_of(P::chin_bottom))]),
            10);
}

}  // namespace
}  // namespace fapc::head3d
