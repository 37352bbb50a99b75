#include "reference_raster.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "fapc/face/face_model.hpp"
#include "fapc/head3d/head_mesh.hpp"

namespace fapc::head3d::reference {

namespace {

using V = std::array<double, 3>;

V sub(V a, V b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
V add(V a, V b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
double dot(V a, V b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
V cross(V a, V b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
V unit(V a) {
  const double n = std::sqrt(dot(a, a));
  return {a[0] / n, a[1] / n, a[2] / n};
}
V metres(Vec3 p) { return {p.x * 1e-3, p.y * 1e-3, p.z * 1e-3}; }

// v turned by the unit quaternion q = (x, y, z, w): v + 2w (u x v) + 2 u x (u x v).
V rotate(const Quaternion& q, V v) {
  const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  const V u{q[0] / n, q[1] / n, q[2] / n};
  const double w = q[3] / n;
  const V t = cross(u, v);
  const V t2 = cross(u, t);
  return {v[0] + 2 * (w * t[0] + t2[0]), v[1] + 2 * (w * t[1] + t2[1]), v[2] + 2 * (w * t[2] + t2[2])};
}

struct Projected {
  double x = 0, y = 0;  // pixels, y down
  double inverse_depth = 0;
  bool in_front = false;
  double motion = 0;  // millimetres, to the same point in the other frame
};

class Rasteriser {
 public:
  Rasteriser(const Camera& c, int w, int h)
      : image_{w, h, std::vector<int>(static_cast<std::size_t>(w) * h, -1),
               std::vector<double>(static_cast<std::size_t>(w) * h, 0.0)} {
    depth_.assign(image_.material.size(), 0.0);  // 1 / depth: larger is nearer; 0 is infinitely far
    eye_ = c.position;
    back_ = unit(sub(c.position, c.target));  // three.js's camera looks down its -z
    right_ = unit(cross({0, 1, 0}, back_));
    up_ = cross(back_, right_);
    focal_ = 1 / std::tan(c.fov_degrees / 2 * M_PI / 180);
    aspect_ = c.aspect;
  }

  Projected project(V p) const {
    const V d = sub(p, eye_);
    const double z = -dot(d, back_);  // distance in front of the camera
    Projected out;
    if (z <= 0.01) return out;  // the camera's near plane
    const double ndc_x = focal_ / aspect_ * dot(d, right_) / z, ndc_y = focal_ * dot(d, up_) / z;
    out.x = (ndc_x + 1) / 2 * image_.width;
    out.y = (1 - ndc_y) / 2 * image_.height;
    out.inverse_depth = 1 / z;
    out.in_front = true;
    return out;
  }

  void triangle(const Projected& a, const Projected& b, const Projected& c, int material) {
    if (!a.in_front || !b.in_front || !c.in_front) return;
    // Counter-clockwise seen from outside is clockwise on a y-down screen: others face away.
    const double area = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
    if (area >= 0) return;
    const int x0 = std::max(0, static_cast<int>(std::floor(std::min({a.x, b.x, c.x}))));
    const int x1 = std::min(image_.width - 1, static_cast<int>(std::ceil(std::max({a.x, b.x, c.x}))));
    const int y0 = std::max(0, static_cast<int>(std::floor(std::min({a.y, b.y, c.y}))));
    const int y1 = std::min(image_.height - 1, static_cast<int>(std::ceil(std::max({a.y, b.y, c.y}))));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const double px = x + 0.5, py = y + 0.5;
        const double wa = ((b.x - px) * (c.y - py) - (c.x - px) * (b.y - py)) / area;
        const double wb = ((c.x - px) * (a.y - py) - (a.x - px) * (c.y - py)) / area;
        const double wc = 1 - wa - wb;
        if (wa < 0 || wb < 0 || wc < 0) continue;
        const double inverse_depth = wa * a.inverse_depth + wb * b.inverse_depth + wc * c.inverse_depth;
        const std::size_t i = static_cast<std::size_t>(y) * image_.width + x;
        if (inverse_depth <= depth_[i]) continue;
        depth_[i] = inverse_depth;
        image_.material[i] = material;
        image_.motion[i] = wa * a.motion + wb * b.motion + wc * c.motion;
      }
  }

  MaterialImage take() { return std::move(image_); }

 private:
  MaterialImage image_;
  std::vector<double> depth_;
  V eye_{}, back_{}, right_{}, up_{};
  double focal_ = 1, aspect_ = 1;
};

void draw_parts(Rasteriser& r, const std::vector<Part>& parts, const std::vector<Projected>& points) {
  for (const Part& part : parts)
    for (std::size_t i = 0; i + 2 < part.triangles.size(); i += 3)
      r.triangle(points[part.triangles[i]], points[part.triangles[i + 1]], points[part.triangles[i + 2]],
                 static_cast<int>(part.material));
}

}  // namespace

// Every vertex of the head and of both eyeballs in scene coordinates (metres), for one frame: the
// head turns about 7.1 (its node's origin); the eyes turn about their centres, inside it.
std::vector<V> scene_vertices(const HeadFrame& frame) {
  const V pivot = metres(face::neutral(face::P::spine_top));
  std::vector<V> out;
  for (const Vec3& p : morphed_positions(frame.weights))
    out.push_back(add(pivot, rotate(frame.head, sub(metres(p), pivot))));
  for (int e = 0; e < 2; ++e) {
    const V centre = sub(metres(eyeball_centre(e)), pivot);
    for (const Vec3& p : eyeball_mesh().positions)
      out.push_back(add(pivot, rotate(frame.head, add(centre, rotate(frame.eyes[e], metres(p))))));
  }
  return out;
}

MaterialImage rasterise_frame(const HeadFrame& frame, const Camera& camera, int width, int height,
                              const HeadFrame* other) {
  Rasteriser r(camera, width, height);
  const std::vector<V> here = scene_vertices(frame);
  const std::vector<V> there = other ? scene_vertices(*other) : here;
  std::vector<Projected> points;
  for (std::size_t i = 0; i < here.size(); ++i) {
    points.push_back(r.project(here[i]));
    const V d = sub(here[i], there[i]);
    points.back().motion = std::sqrt(dot(d, d)) * 1e3;
  }
  const std::size_t head = head_mesh().positions.size(), eye = eyeball_mesh().positions.size();
  draw_parts(r, head_mesh().parts, points);
  for (std::size_t e = 0; e < 2; ++e) {
    const std::vector<Projected> eye_points(points.begin() + static_cast<std::ptrdiff_t>(head + e * eye),
                                            points.begin() + static_cast<std::ptrdiff_t>(head + (e + 1) * eye));
    draw_parts(r, eyeball_mesh().parts, eye_points);
  }
  return r.take();
}

}  // namespace fapc::head3d::reference
