// fapc's 3D head: a triangle mesh generated at run time, deterministically, around the neutral
// face's feature points (fapc::face's model is the one source of them), with eye openings and a
// mouth that parts, eyeballs, teeth, a tongue and ears. Every vertex is bound to a few anchors
// (feature points and points the 3D head adds); a FAP moves a vertex by the weighted sum of its
// anchors' displacements. docs/render.md, "The 3D head", describes the construction.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

#include "fapc/face/face_model.hpp"

namespace fapc::head3d {

using face::Vec3;

// What a group of triangles is drawn with; glTF writes one material per kind.
enum class Material : int { skin, hair, lips, mouth, teeth, tongue, sclera, iris, pupil, count };
std::string_view material_name(Material m);
// Base colour, linear RGB.
std::array<double, 3> material_colour(Material m);

struct Part {
  Material material;
  std::vector<std::uint32_t> triangles;  // three vertex indices each, counter-clockwise seen from outside
};

// Where a point that moves with the face sits and how it follows the feature points: an anchor is
// either a feature (or contour) point of fapc::face, or a point the 3D head adds that follows one of
// them by a weight (the lid quarter points), or a fixed point of the skull.
struct Anchor {
  Vec3 position;      // neutral, millimetres, face coordinates
  int point = -1;     // fapc::face::P it follows, or -1 for a fixed point
  double weight = 1;  // how much of that point's displacement it takes
};

// Up to four anchors per vertex, weights summing to 1.
struct Binding {
  std::array<int, 4> anchor{-1, -1, -1, -1};
  std::array<double, 4> weight{};
};

struct HeadMesh {
  std::vector<Vec3> positions;  // millimetres, face coordinates (x to the face's left, y up, z out)
  std::vector<Vec3> normals;    // unit, smooth (area-weighted face normals)
  std::vector<Binding> bindings;
  std::vector<Anchor> anchors;
  std::vector<Part> parts;  // the head's skin (closed with its eye and mouth pockets), teeth, tongue, ears
  // Vertices that lie on an eyelid (index into `positions`), with the eye they belong to (0 left,
  // 1 right): a lid's targets keep them outside the eyeball.
  std::vector<std::pair<std::uint32_t, int>> lid_vertices;
  // The vertex at each standard feature point the tests and docs measure (nearest to the point on
  // its side of the openings), by fapc::face::P; -1 where the mesh has none (7.1, the pupils).
  std::array<int, face::kPointCount> feature_vertex{};
};

// The eyeball: a sphere of fapc::face::kEyeballRadius about the origin, its pupil on +z; sclera,
// iris and pupil as three parts. Both eyes use it, each on its own node.
struct EyeballMesh {
  std::vector<Vec3> positions;
  std::vector<Vec3> normals;
  std::vector<Part> parts;
};

// Built once (the same bytes every time), shared.
const HeadMesh& head_mesh();
const EyeballMesh& eyeball_mesh();

// The centre of the left (0) or right (1) eyeball on the neutral face.
Vec3 eyeball_centre(int eye);
// The lids lie on a sphere of this radius about the eyeball's centre, just outside the eyeball.
inline constexpr double kLidRadius = 13.3;

}  // namespace fapc::head3d
