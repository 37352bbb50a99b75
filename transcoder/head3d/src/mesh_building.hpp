// The pieces the head is assembled from (head_mesh.cpp): the skin's surface with its openings,
// the small closed parts (teeth, tongue, ears) and the eyeball, written into one vertex list.
#pragma once

#include <cstdint>
#include <vector>

#include "fapc/head3d/head_mesh.hpp"

namespace fapc::head3d {

// Which side of an opening a vertex or an anchor is on: a vertex never binds to an anchor on the
// other side of the same opening, so an upper lip does not follow the jaw and a lid does not
// follow the other lid.
enum class Side : int { any, mouth_upper, mouth_lower, eye_l_upper, eye_l_lower, eye_r_upper, eye_r_lower };
bool opposite(Side a, Side b);

struct MeshBuilder {
  std::vector<Vec3> positions;
  std::vector<Side> sides;
  std::vector<Part> parts;

  std::uint32_t add(Vec3 p, Side side);
  Part& part(Material m);  // the part of that material, created on first use
  void triangle(Material m, std::uint32_t a, std::uint32_t b, std::uint32_t c);
};

// The skin: a closed surface with an almond opening per eye, a slit mouth, and pockets behind them
// (eye sockets, the mouth's inside) that keep it closed. Appends to `mesh`; `lids` gets the
// vertices on or near an eyelid.
void build_skin(MeshBuilder& mesh, std::vector<std::pair<std::uint32_t, int>>& lids);

// Teeth (upper and lower arches), the tongue, and the two ears: closed solids.
void build_mouth_parts(MeshBuilder& mesh);
void build_ears(MeshBuilder& mesh);

// A closed ellipsoid (UV sphere scaled), outward faces.
void add_ellipsoid(MeshBuilder& mesh, Material m, Side side, Vec3 centre, Vec3 radii, int rings, int segments);

// Outward orientation for a convex-ish closed part: each triangle faces away from `inside`.
void orient_from(MeshBuilder& mesh, Material m, std::size_t first_triangle, Vec3 inside);

// Vector helpers.
double dot(Vec3 a, Vec3 b);
Vec3 cross(Vec3 a, Vec3 b);
double length(Vec3 a);
Vec3 normalized(Vec3 a);

// Smooth vertex normals: the sum of the area-weighted normals of the triangles around each vertex.
std::vector<Vec3> smooth_normals(const std::vector<Vec3>& positions, const std::vector<Part>& parts);

}  // namespace fapc::head3d
