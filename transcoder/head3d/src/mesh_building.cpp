#include "mesh_building.hpp"

#include <cmath>
#include <numbers>

namespace fapc::head3d {

bool opposite(Side a, Side b) {
  auto pair = [](Side s) { return (static_cast<int>(s) - 1) / 2; };  // mouth 0, left eye 1, right eye 2
  return a != Side::any && b != Side::any && a != b && pair(a) == pair(b);
}

std::uint32_t MeshBuilder::add(Vec3 p, Side side) {
  positions.push_back(p);
  sides.push_back(side);
  return static_cast<std::uint32_t>(positions.size() - 1);
}

Part& MeshBuilder::part(Material m) {
  for (Part& p : parts)
    if (p.material == m) return p;
  parts.push_back(Part{m, {}});
  return parts.back();
}

void MeshBuilder::triangle(Material m, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  std::vector<std::uint32_t>& t = part(m).triangles;
  t.insert(t.end(), {a, b, c});
}

double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec3 cross(Vec3 a, Vec3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
double length(Vec3 a) { return std::sqrt(dot(a, a)); }
Vec3 normalized(Vec3 a) {
  const double l = length(a);
  return l > 0 ? (1 / l) * a : Vec3{0, 0, 1};
}

void add_ellipsoid(MeshBuilder& mesh, Material m, Side side, Vec3 centre, Vec3 radii, int rings, int segments) {
  const std::size_t first = mesh.part(m).triangles.size() / 3;
  const std::uint32_t south = mesh.add(centre - Vec3{0, radii.y, 0}, side);
  std::vector<std::uint32_t> ids;
  for (int r = 1; r < rings; ++r) {
    const double phi = -std::numbers::pi / 2 + std::numbers::pi * r / rings;
    for (int s = 0; s < segments; ++s) {
      const double theta = 2 * std::numbers::pi * s / segments;
      ids.push_back(mesh.add(centre + Vec3{radii.x * std::cos(phi) * std::sin(theta), radii.y * std::sin(phi),
                                           radii.z * std::cos(phi) * std::cos(theta)},
                             side));
    }
  }
  const std::uint32_t north = mesh.add(centre + Vec3{0, radii.y, 0}, side);
  auto id = [&](int r, int s) { return ids[static_cast<std::size_t>(r * segments + (s % segments))]; };
  for (int s = 0; s < segments; ++s) {
    mesh.triangle(m, south, id(0, s), id(0, s + 1));
    mesh.triangle(m, north, id(rings - 2, s), id(rings - 2, s + 1));
    for (int r = 0; r + 1 < rings - 1; ++r) {
      mesh.triangle(m, id(r, s), id(r, s + 1), id(r + 1, s + 1));
      mesh.triangle(m, id(r, s), id(r + 1, s + 1), id(r + 1, s));
    }
  }
  orient_from(mesh, m, first, centre);
}

void orient_from(MeshBuilder& mesh, Material m, std::size_t first_triangle, Vec3 inside) {
  std::vector<std::uint32_t>& t = mesh.part(m).triangles;
  for (std::size_t i = first_triangle * 3; i + 2 < t.size(); i += 3) {
    const Vec3 a = mesh.positions[t[i]], b = mesh.positions[t[i + 1]], c = mesh.positions[t[i + 2]];
    const Vec3 centroid = (1.0 / 3) * (a + b + c);
    if (dot(cross(b - a, c - a), centroid - inside) < 0) std::swap(t[i + 1], t[i + 2]);
  }
}

std::vector<Vec3> smooth_normals(const std::vector<Vec3>& positions, const std::vector<Part>& parts) {
  std::vector<Vec3> sum(positions.size());
  for (const Part& part : parts)
    for (std::size_t i = 0; i + 2 < part.triangles.size(); i += 3) {
      const std::uint32_t a = part.triangles[i], b = part.triangles[i + 1], c = part.triangles[i + 2];
      const Vec3 n = cross(positions[b] - positions[a], positions[c] - positions[a]);  // length = 2 x area
      for (std::uint32_t v : {a, b, c}) sum[v] = sum[v] + n;
    }
  for (Vec3& n : sum) n = normalized(n);
  return sum;
}

}  // namespace fapc::head3d
