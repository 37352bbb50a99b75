// The small closed parts inside and beside the skin: the two arches of teeth, the tongue and the
// ears, our own shapes placed by the face model's contour points (docs/render.md).
#include <algorithm>
#include <array>
#include <cmath>

#include "fapc/face/face_model.hpp"
#include "mesh_building.hpp"

namespace fapc::head3d {

namespace {

using face::P;

// An arch of teeth: a box section (height from `bottom` to `top`, 3 mm deep) swept along a
// parabola whose front is at the contour point's z and whose ends reach 12 mm back, a little past
// the biting edge's ends. Closed with end caps; every face turned away from the box's inside.
void add_arch(MeshBuilder& mesh, Side side, Vec3 left_edge, double bottom, double top) {
  constexpr int kSamples = 17;
  constexpr double kDepth = 3, kBack = 12;
  const double half = left_edge.x * 1.35;
  auto front_at = [&](double s) { return Vec3{half * s, 0, left_edge.z - kBack * s * s}; };
  auto tangent_at = [&](double s) { return normalized(Vec3{half, 0, -2 * kBack * s}); };
  auto inward_at = [&](double s) { return normalized(Vec3{-2 * kBack * s, 0, -half}); };
  std::vector<std::array<std::uint32_t, 4>> sections;
  for (int i = 0; i < kSamples; ++i) {
    const double s = -1 + 2.0 * i / (kSamples - 1);
    const Vec3 front = front_at(s), back = front + kDepth * inward_at(s);
    sections.push_back({mesh.add(Vec3{front.x, top, front.z}, side), mesh.add(Vec3{front.x, bottom, front.z}, side),
                        mesh.add(Vec3{back.x, bottom, back.z}, side), mesh.add(Vec3{back.x, top, back.z}, side)});
  }
  // A triangle facing `out`.
  auto facing = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c, Vec3 out) {
    const Vec3 pa = mesh.positions[a], pb = mesh.positions[b], pc = mesh.positions[c];
    if (dot(cross(pb - pa, pc - pa), out) < 0) std::swap(b, c);
    mesh.triangle(Material::teeth, a, b, c);
  };
  const double mid_y = (top + bottom) / 2;
  for (std::size_t i = 0; i + 1 < sections.size(); ++i) {
    const double s = -1 + (2.0 * static_cast<double>(i) + 1) / (kSamples - 1);
    const Vec3 centre = front_at(s) + (kDepth / 2) * inward_at(s) + Vec3{0, mid_y, 0};
    for (std::size_t k = 0; k < 4; ++k) {
      const std::uint32_t a = sections[i][k], b = sections[i][(k + 1) % 4];
      const std::uint32_t c = sections[i + 1][(k + 1) % 4], d = sections[i + 1][k];
      const Vec3 out =
          (0.25 * (mesh.positions[a] + mesh.positions[b] + mesh.positions[c] + mesh.positions[d])) - centre;
      facing(a, b, c, out);
      facing(a, c, d, out);
    }
  }
  for (const double s : {-1.0, 1.0}) {
    const auto& end = s < 0 ? sections.front() : sections.back();
    const Vec3 out = s * tangent_at(s);
    facing(end[0], end[1], end[2], out);
    facing(end[0], end[2], end[3], out);
  }
}

}  // namespace

void build_mouth_parts(MeshBuilder& mesh) {
  const Vec3 upper = face::neutral(P::teeth_t_l), lower = face::neutral(P::teeth_b_l);
  add_arch(mesh, Side::mouth_upper, upper, upper.y, upper.y + 8);
  add_arch(mesh, Side::mouth_lower, Vec3{lower.x, lower.y, lower.z - 2.5}, lower.y - 8, lower.y);
  // The tongue: an ellipsoid whose front reaches the tip (6.1) and whose middle is near 6.2.
  const Vec3 tip = face::neutral(P::tongue_tip);
  add_ellipsoid(mesh, Material::tongue, Side::mouth_lower, Vec3{0, tip.y - 3.5, tip.z - 14}, Vec3{15, 4.5, 14}, 8, 16);
}

void build_ears(MeshBuilder& mesh) {
  for (P top : {P::ear_l_top, P::ear_r_top}) {
    const bool left = top == P::ear_l_top;
    const Vec3 t = face::neutral(top), lobe = face::neutral(left ? P::ear_l_lobe : P::ear_r_lobe);
    const Vec3 front = face::neutral(left ? P::ear_l_front : P::ear_r_front);
    const Vec3 back = face::neutral(left ? P::ear_l_back : P::ear_r_back);
    const Vec3 centre{(t.x + lobe.x) / 2 + (left ? 2 : -2), (t.y + lobe.y) / 2, (front.z + back.z) / 2};
    add_ellipsoid(mesh, Material::skin, Side::any, centre, Vec3{5, (t.y - lobe.y) / 2 + 1, (front.z - back.z) / 2 + 1},
                  8, 14);
  }
}

}  // namespace fapc::head3d
