// The head assembled: skin, mouth parts and ears in one vertex list, every vertex bound to its
// nearest anchors on its side of the openings; the eyeball on its own.
#include "fapc/head3d/head_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "mesh_building.hpp"

namespace fapc::head3d {

namespace {

using face::P;

std::string_view kMaterialNames[] = {"skin", "hair", "lips", "mouth", "teeth", "tongue", "sclera", "iris", "pupil"};
// Linear RGB base colours, our own.
constexpr std::array<double, 3> kMaterialColours[] = {{0.80, 0.52, 0.40}, {0.16, 0.09, 0.05}, {0.62, 0.22, 0.22},
                                                      {0.22, 0.03, 0.04}, {0.90, 0.88, 0.80}, {0.65, 0.20, 0.22},
                                                      {0.92, 0.92, 0.90}, {0.12, 0.25, 0.42}, {0.01, 0.01, 0.01}};

// Which side of an opening a feature point is on (the lower lip and everything the jaw carries are
// below the mouth; a lid and its brow are above the eye, the lower lid below).
Side side_of_point(P p) {
  switch (p) {
    case P::lip_t_mid_i:
    case P::lip_t_lm_i:
    case P::lip_t_rm_i:
    case P::lip_t_mid_o:
    case P::lip_t_lm_o:
    case P::lip_t_rm_o:
    case P::teeth_t_l:
    case P::teeth_t_r:
    case P::nose_base:
    case P::nose_l:
    case P::nose_r:
      return Side::mouth_upper;
    case P::lip_b_mid_i:
    case P::lip_b_lm_i:
    case P::lip_b_rm_i:
    case P::lip_b_mid_o:
    case P::lip_b_lm_o:
    case P::lip_b_rm_o:
    case P::teeth_b_l:
    case P::teeth_b_r:
    case P::tongue_tip:
    case P::tongue_body:
    case P::chin_bottom:
    case P::chin_boss:
    case P::chin_l:
    case P::chin_r:
      return Side::mouth_lower;
    case P::lid_t_l:
    case P::brow_l_inner:
    case P::brow_l_mid:
    case P::brow_l_outer:
      return Side::eye_l_upper;
    case P::lid_b_l:
      return Side::eye_l_lower;
    case P::lid_t_r:
    case P::brow_r_inner:
    case P::brow_r_mid:
    case P::brow_r_outer:
      return Side::eye_r_upper;
    case P::lid_b_r:
      return Side::eye_r_lower;
    default:
      return Side::any;
  }
}

struct SidedAnchor {
  Anchor anchor;
  Side side;
};

// Points of the skull no FAP moves: they hold the back and the top of the head still.
constexpr Vec3 kFixedPoints[] = {{0, 121, -22},  {60, 60, -40},   {-60, 60, -40}, {0, 60, -100},  {0, 20, -106},
                                 {72, 10, -40},  {-72, 10, -40},  {50, 20, -90},  {-50, 20, -90}, {0, -40, -72},
                                 {45, -50, -55}, {-45, -50, -55}, {0, -110, -20}, {0, -90, -50},  {60, 90, -60},
                                 {-60, 90, -60}, {0, 100, 0},     {40, 100, 0},   {-40, 100, 0},  {0, 40, 37}};

std::vector<SidedAnchor> anchors() {
  std::vector<SidedAnchor> out;
  for (const face::FacePoint& fp : face::face_points()) {
    if (fp.id == P::spine_top || fp.id == P::pupil_l || fp.id == P::pupil_r) continue;
    out.push_back({{fp.neutral, static_cast<int>(fp.id), 1}, side_of_point(fp.id)});
  }
  // The lids' quarter points: on the lid's arc halfway to each corner, following the lid's middle
  // by 1 - t^2 = 0.75, as the lid's arc through its middle and corners does.
  for (int e = 0; e < 2; ++e) {
    const Vec3 c = eyeball_centre(e);
    const P inner = e == 0 ? P::eye_l_inner : P::eye_r_inner, outer = e == 0 ? P::eye_l_outer : P::eye_r_outer;
    const double mid_x = (face::neutral(inner).x + face::neutral(outer).x) / 2;
    const double quarter = std::abs(face::neutral(outer).x - face::neutral(inner).x) / 4;
    for (const bool upper : {true, false}) {
      const P lid = e == 0 ? (upper ? P::lid_t_l : P::lid_b_l) : (upper ? P::lid_t_r : P::lid_b_r);
      const double y = 0.75 * (face::neutral(lid).y);
      for (const double dx : {-quarter, quarter}) {
        const double x = mid_x + dx;
        const double z = c.z + std::sqrt(std::max(kLidRadius * kLidRadius - (x - c.x) * (x - c.x) - y * y, 0.0));
        out.push_back({{Vec3{x, y, z}, static_cast<int>(lid), 0.75}, side_of_point(lid)});
      }
    }
  }
  for (const Vec3& p : kFixedPoints) out.push_back({{p, -1, 1}, Side::any});
  return out;
}

// The four nearest anchors not across an opening, weighted by 1 / (d^2 + 0.1)^2: a vertex on an
// anchor follows it (almost) alone, and the weights fall off fast so that features stay local.
Binding bind(Vec3 p, Side side, const std::vector<SidedAnchor>& all) {
  std::array<std::pair<double, int>, 4> best;
  best.fill({std::numeric_limits<double>::infinity(), -1});
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (opposite(side, all[i].side)) continue;
    const Vec3 d = p - all[i].anchor.position;
    const double d2 = dot(d, d);
    if (d2 < best.back().first) {
      best.back() = {d2, static_cast<int>(i)};
      std::sort(best.begin(), best.end());
    }
  }
  Binding b;
  double sum = 0;
  for (std::size_t k = 0; k < 4; ++k) {
    b.anchor[k] = best[k].second;
    b.weight[k] = best[k].second < 0 ? 0 : 1 / ((best[k].first + 0.1) * (best[k].first + 0.1));
    sum += b.weight[k];
  }
  for (double& w : b.weight) w /= sum;
  return b;
}

HeadMesh build() {
  MeshBuilder builder;
  HeadMesh mesh;
  build_skin(builder, mesh.lid_vertices);
  build_mouth_parts(builder);
  build_ears(builder);
  const std::vector<SidedAnchor> sided = anchors();
  for (const SidedAnchor& a : sided) mesh.anchors.push_back(a.anchor);
  mesh.positions = builder.positions;
  mesh.parts = builder.parts;
  std::sort(mesh.parts.begin(), mesh.parts.end(), [](const Part& a, const Part& b) { return a.material < b.material; });
  mesh.normals = smooth_normals(mesh.positions, mesh.parts);
  for (std::size_t v = 0; v < mesh.positions.size(); ++v)
    mesh.bindings.push_back(bind(mesh.positions[v], builder.sides[v], sided));
  // The vertex that stands for each feature point: the nearest one on the point's side (or on no
  // side: away from the openings).
  for (const face::FacePoint& fp : face::face_points()) {
    int best = -1;
    double best_d = std::numeric_limits<double>::infinity();
    const Side side = side_of_point(fp.id);
    if (fp.id != P::spine_top && fp.id != P::pupil_l && fp.id != P::pupil_r)
      for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        if (side != Side::any && builder.sides[v] != side && builder.sides[v] != Side::any) continue;
        const double d = length(mesh.positions[v] - fp.neutral);
        if (d < best_d) best_d = d, best = static_cast<int>(v);
      }
    mesh.feature_vertex[static_cast<std::size_t>(fp.id)] = best;
  }
  return mesh;
}

EyeballMesh build_eyeball() {
  // A sphere with its pole on +z: the pupil and the iris are caps about the pole (IRISD0/3 and
  // IRISD0 across, as the 2D face draws them), the sclera the rest.
  MeshBuilder b;
  const double r = face::kEyeballRadius;
  const double pupil = std::asin(face::fapus().irisd0 / 6 / r), iris = std::asin(face::fapus().irisd0 / 2 / r);
  constexpr int kSegments = 24;
  struct Band {
    Material m;
    double from, to;
    int rings;
  };
  const Band bands[] = {
      {Material::pupil, 0, pupil, 2}, {Material::iris, pupil, iris, 3}, {Material::sclera, iris, std::numbers::pi, 12}};
  auto at = [&](double polar, double azimuth) {
    return Vec3{r * std::sin(polar) * std::cos(azimuth), r * std::sin(polar) * std::sin(azimuth), r * std::cos(polar)};
  };
  for (const Band& band : bands) {
    std::vector<std::vector<std::uint32_t>> rings;
    for (int k = 0; k <= band.rings; ++k) {
      const double polar = band.from + (band.to - band.from) * k / band.rings;
      std::vector<std::uint32_t> ring;
      const bool pole = polar == 0 || std::abs(polar - std::numbers::pi) < 1e-12;
      for (int s = 0; s < (pole ? 1 : kSegments); ++s)
        ring.push_back(b.add(at(polar, 2 * std::numbers::pi * s / kSegments), Side::any));
      rings.push_back(ring);
    }
    auto id = [&](std::size_t ring, int i) {
      return rings[ring][static_cast<std::size_t>(i % kSegments) % rings[ring].size()];
    };
    for (std::size_t k = 0; k + 1 < rings.size(); ++k)
      for (int s = 0; s < kSegments; ++s) {
        const std::uint32_t a = id(k, s), c = id(k + 1, s + 1), d = id(k + 1, s);
        if (rings[k].size() > 1) b.triangle(band.m, a, id(k, s + 1), c);
        if (rings[k + 1].size() > 1) b.triangle(band.m, a, c, d);
      }
    orient_from(b, band.m, 0, Vec3{});
  }
  EyeballMesh eye;
  eye.positions = b.positions;
  eye.parts = b.parts;
  eye.normals.reserve(eye.positions.size());
  for (const Vec3& p : eye.positions) eye.normals.push_back(normalized(p));
  return eye;
}

}  // namespace

std::string_view material_name(Material m) { return kMaterialNames[static_cast<int>(m)]; }
std::array<double, 3> material_colour(Material m) { return kMaterialColours[static_cast<int>(m)]; }

const HeadMesh& head_mesh() {
  static const HeadMesh mesh = build();
  return mesh;
}

const EyeballMesh& eyeball_mesh() {
  static const EyeballMesh mesh = build_eyeball();
  return mesh;
}

}  // namespace fapc::head3d
