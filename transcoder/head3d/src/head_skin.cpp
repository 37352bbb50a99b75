// The skin of the 3D head. Rows of constant height y (3 mm apart over the face, 5 mm elsewhere)
// and columns at angles lambda about a vertical axis (denser at the front): each row is an ellipse
// (half-width, front and back from a table of our own), and the face is pulled onto the feature
// points by a smooth offset interpolated between them (Gaussian radial basis functions over the
// (angle, height) plane). The eye region is pushed out onto a sphere just outside the eyeball
// (the lids); the eyes open as almonds on the row y = 0 and the mouth as a slit on the row of the
// inner lips; behind each opening a pocket keeps the skin closed.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "fapc/face/face_model.hpp"
#include "mesh_building.hpp"

namespace fapc::head3d {

namespace {

using face::P;
constexpr double kPi = std::numbers::pi;

// The head's horizontal section at height y: half-width a, front z and back z at the middle.
struct Section {
  double y, a, front, back;
};
// Our own numbers, read off the feature points: the chin, the jaw angles, the cheeks, the brows,
// the hairline and the top of the head (docs/render.md lists the points).
constexpr Section kSections[] = {
    {-114, 0, -5, -5},  {-108, 24, 22, -40}, {-100, 38, 32, -52}, {-90, 50, 35, -58},
    {-72, 62, 37, -62}, {-66, 62, 38, -64},  {-40, 64, 38, -72},  {-20, 68, 40, -85},
    {0, 72, 40, -100},  {17, 74, 40, -105},  {40, 74, 37, -106},  {66, 68, 28, -100},
    {90, 56, 10, -85},  {110, 35, -8, -60},  {118, 20, -14, -42}, {122, 0, -22, -22},
};

double hermite(double y, double Section::*field) {
  constexpr int n = static_cast<int>(std::size(kSections));
  int i = 0;
  while (i < n - 2 && y > kSections[i + 1].y) ++i;
  const Section& s0 = kSections[i];
  const Section& s1 = kSections[i + 1];
  auto slope = [&](int k) {
    const int lo = std::max(k - 1, 0), hi = std::min(k + 1, n - 1);
    return (kSections[hi].*field - kSections[lo].*field) / (kSections[hi].y - kSections[lo].y);
  };
  const double h = s1.y - s0.y, t = std::clamp((y - s0.y) / h, 0.0, 1.0);
  const double t2 = t * t, t3 = t2 * t;
  return (2 * t3 - 3 * t2 + 1) * (s0.*field) + (t3 - 2 * t2 + t) * h * slope(i) + (-2 * t3 + 3 * t2) * (s1.*field) +
         (t3 - t2) * h * slope(i + 1);
}

struct Ellipse {
  double a, centre, b;  // half-width, z of the centre, half-depth
};
Ellipse section_at(double y) {
  const double a = std::max(hermite(y, &Section::a), 0.0);
  const double front = hermite(y, &Section::front), back = hermite(y, &Section::back);
  return {a, (front + back) / 2, std::max((front - back) / 2, 0.0)};
}
Vec3 on_section(double y, double lambda) {
  const Ellipse e = section_at(y);
  return {e.a * std::sin(lambda), y, e.centre + e.b * std::cos(lambda)};
}
double angle_of(Vec3 p) {
  const Ellipse e = section_at(p.y);
  return std::atan2(p.x / std::max(e.a, 1e-6), (p.z - e.centre) / std::max(e.b, 1e-6));
}

// The offset field: Gaussian radial basis functions over (lambda x kArc, y) that move the
// sections onto the feature points exactly (x and z offsets interpolated separately).
constexpr double kArc = 60;   // millimetres per radian of lambda in the interpolation plane
constexpr double kSigma = 9;  // width of each basis function, millimetres
struct OffsetField {
  std::vector<double> u, v, cx, cz;
  Vec3 at(double y, double lambda) const {
    double dx = 0, dz = 0;
    for (std::size_t i = 0; i < u.size(); ++i) {
      const double du = lambda * kArc - u[i], dv = y - v[i];
      const double k = std::exp(-(du * du + dv * dv) / (2 * kSigma * kSigma));
      dx += cx[i] * k;
      dz += cz[i] * k;
    }
    return {dx, 0, dz};
  }
};

// Solves A x = b (A symmetric positive definite, small) by Gaussian elimination with pivoting.
std::vector<double> solve(std::vector<std::vector<double>> a, std::vector<double> b) {
  const std::size_t n = b.size();
  for (std::size_t c = 0; c < n; ++c) {
    std::size_t pivot = c;
    for (std::size_t r = c + 1; r < n; ++r)
      if (std::abs(a[r][c]) > std::abs(a[pivot][c])) pivot = r;
    std::swap(a[c], a[pivot]);
    std::swap(b[c], b[pivot]);
    for (std::size_t r = c + 1; r < n; ++r) {
      const double f = a[r][c] / a[c][c];
      for (std::size_t k = c; k < n; ++k) a[r][k] -= f * a[c][k];
      b[r] -= f * b[c];
    }
  }
  std::vector<double> x(n);
  for (std::size_t i = n; i-- > 0;) {
    double s = b[i];
    for (std::size_t k = i + 1; k < n; ++k) s -= a[i][k] * x[k];
    x[i] = s / a[i][i];
  }
  return x;
}

// The feature points the skin passes through (not the lids, which lie on the eyeball's sphere,
// nor the ears, which are parts of their own).
constexpr P kSkinPoints[] = {
    P::chin_bottom,  P::chin_boss,      P::chin_l,         P::chin_r,         P::jaw_angle_l,    P::jaw_angle_r,
    P::lip_t_mid_i,  P::lip_t_lm_i,     P::lip_t_rm_i,     P::lip_l_corner_i, P::lip_r_corner_i, P::lip_t_mid_o,
    P::lip_b_mid_o,  P::lip_l_corner_o, P::lip_r_corner_o, P::lip_t_lm_o,     P::lip_t_rm_o,     P::lip_b_lm_o,
    P::lip_b_rm_o,   P::eye_l_outer,    P::eye_l_inner,    P::eye_r_outer,    P::eye_r_inner,    P::brow_l_inner,
    P::brow_r_inner, P::brow_l_mid,     P::brow_r_mid,     P::brow_l_outer,   P::brow_r_outer,   P::cheek_l_side,
    P::cheek_r_side, P::cheek_l,        P::cheek_r,        P::cheek_l_upper,  P::cheek_r_upper,  P::nose_l,
    P::nose_r,       P::nose_tip,       P::nose_base,      P::nose_bridge,    P::hairline,       P::head_top};

OffsetField offset_field() {
  OffsetField f;
  std::vector<double> ox, oz;
  for (P p : kSkinPoints) {
    const Vec3 q = face::neutral(p);
    const double lambda = angle_of(q);
    const Vec3 base = on_section(q.y, lambda);
    f.u.push_back(lambda * kArc);
    f.v.push_back(q.y);
    ox.push_back(q.x - base.x);
    oz.push_back(q.z - base.z);
  }
  const std::size_t n = f.u.size();
  std::vector<std::vector<double>> k(n, std::vector<double>(n));
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) {
      const double du = f.u[i] - f.u[j], dv = f.v[i] - f.v[j];
      k[i][j] = std::exp(-(du * du + dv * dv) / (2 * kSigma * kSigma)) + (i == j ? 1e-9 : 0);
    }
  f.cx = solve(k, ox);
  f.cz = solve(k, oz);
  return f;
}

// Heights of the rows, bottom to top, without the two poles: 3 mm from the chin to the brows (so
// that y = -66, the inner lips, and y = 0, the eyes' corners, are rows), 5 mm above.
std::vector<double> row_heights() {
  std::vector<double> ys;
  for (int k = 0; k <= 42; ++k) ys.push_back(-111 + 3 * k);
  for (double y = 20; y <= 115; y += 5) ys.push_back(y);
  return ys;
}
constexpr double kMouthRow = -66, kEyeRow = 0;

// Angles of the columns: uniform in theta, lambda = theta - 0.7 sin theta, so the front (where
// the features are) has 3.3 times as many columns per radian as a uniform grid and the back 0.6.
constexpr int kColumns = 112;
double column_angle(int j) {
  const double theta = -kPi + 2 * kPi * j / kColumns;
  return theta - 0.7 * std::sin(theta);
}

// The column nearest to a point's angle.
int column_near(Vec3 p) {
  const double lambda = angle_of(p);
  int best = 0;
  for (int j = 1; j < kColumns; ++j)
    if (std::abs(column_angle(j) - lambda) < std::abs(column_angle(best) - lambda)) best = j;
  return best;
}

// The lips' outline (outer contour) at x: the top and bottom heights, piecewise linear through
// 8.4, 8.6, 8.1, 8.5, 8.3 and 8.4, 8.8, 8.2, 8.7, 8.3.
bool inside_lips(Vec3 c) {
  const double ax = std::abs(c.x);
  const Vec3 corner = face::neutral(P::lip_l_corner_o), top_mid = face::neutral(P::lip_t_lm_o),
             bottom_mid = face::neutral(P::lip_b_lm_o);
  if (ax > corner.x || c.z < 10) return false;
  auto between = [&](double y0, double y1, double x0, double x1) { return y0 + (y1 - y0) * (ax - x0) / (x1 - x0); };
  const double top = ax < top_mid.x ? between(face::neutral(P::lip_t_mid_o).y, top_mid.y, 0, top_mid.x)
                                    : between(top_mid.y, corner.y, top_mid.x, corner.x);
  const double bottom = ax < bottom_mid.x ? between(face::neutral(P::lip_b_mid_o).y, bottom_mid.y, 0, bottom_mid.x)
                                          : between(bottom_mid.y, corner.y, bottom_mid.x, corner.x);
  return c.y <= top && c.y >= bottom;
}

// Hair covers the skin above a line that runs from the hairline (11.1) over the temples and
// above the ears down to the nape: its height by |lambda|, our own numbers.
bool is_hair(Vec3 c) {
  constexpr double kLine[][2] = {{0, 62}, {0.6, 66}, {1.2, 38}, {1.6, 18}, {2.2, -30}, {kPi + 0.01, -45}};
  const double l = std::abs(angle_of(c));
  for (std::size_t i = 0; i + 1 < std::size(kLine); ++i)
    if (l <= kLine[i + 1][0]) {
      const double t = (l - kLine[i][0]) / (kLine[i + 1][0] - kLine[i][0]);
      return c.y > kLine[i][1] + t * (kLine[i + 1][1] - kLine[i][1]);
    }
  return true;
}

// An opening on a row: the columns strictly between `first` and `last` get a second vertex (the
// upper side's); first and last are its corners.
struct Opening {
  int row, first, last;
};

Side eye_side(int eye, bool upper) {
  if (eye == 0) return upper ? Side::eye_l_upper : Side::eye_l_lower;
  return upper ? Side::eye_r_upper : Side::eye_r_lower;
}

}  // namespace

Vec3 eyeball_centre(int eye) {
  return face::neutral(eye == 0 ? P::pupil_l : P::pupil_r) - Vec3{0, 0, face::kEyeballRadius};
}

void build_skin(MeshBuilder& mesh, std::vector<std::pair<std::uint32_t, int>>& lids) {
  const OffsetField offset = offset_field();
  const std::vector<double> ys = row_heights();
  const int rows = static_cast<int>(ys.size());
  const int mouth_row = static_cast<int>(std::find(ys.begin(), ys.end(), kMouthRow) - ys.begin());
  const int eye_row = static_cast<int>(std::find(ys.begin(), ys.end(), kEyeRow) - ys.begin());

  const Opening mouth{mouth_row, column_near(face::neutral(P::lip_r_corner_o)),
                      column_near(face::neutral(P::lip_l_corner_o))};
  const Opening eyes[2] = {
      {eye_row, column_near(face::neutral(P::eye_l_inner)), column_near(face::neutral(P::eye_l_outer))},
      {eye_row, column_near(face::neutral(P::eye_r_outer)), column_near(face::neutral(P::eye_r_inner))}};
  auto eye_of_column = [&](int j) {
    for (int e = 0; e < 2; ++e)
      if (j >= eyes[e].first && j <= eyes[e].last) return e;
    return -1;
  };
  // Where along an opening a column is: -1 at `first`, +1 at `last`.
  auto along = [](const Opening& o, int j) { return -1 + 2.0 * (j - o.first) / (o.last - o.first); };

  // The lids: the rows within 12 mm of the eye row bend so that the opening is an almond of
  // IRISD0 (3.1.y - 3.3.y) at its middle and nothing at its corners.
  const double lid_height = (face::neutral(P::lid_t_l).y - face::neutral(P::lid_b_l).y) / 2;
  auto lid_lift = [&](int j, double y, bool upper_copy) {
    const int e = eye_of_column(j);
    if (e < 0 || std::abs(y - kEyeRow) > 12) return 0.0;
    const double t = along(eyes[e], j);
    const double h = lid_height * (1 - t * t);
    const double fade = 1 - std::abs(y - kEyeRow) / 12;
    if (y > kEyeRow || (y == kEyeRow && upper_copy)) return h * fade;
    return -h * fade;
  };
  auto side_of = [&](Vec3 p, int r, bool upper_copy) {
    if (std::abs(p.x) < 32 && p.y < -50 && p.z > 0) {
      const bool upper = r > mouth_row || (r == mouth_row && upper_copy);
      return upper ? Side::mouth_upper : Side::mouth_lower;
    }
    for (int e = 0; e < 2; ++e) {
      const Vec3 c = eyeball_centre(e);
      if (std::abs(p.x - c.x) < 17 && std::abs(p.y - c.y) < 15 && p.z > c.z) {
        const bool upper = r > eye_row || (r == eye_row && upper_copy);
        return eye_side(e, upper);
      }
    }
    return Side::any;
  };
  auto place = [&](int r, int j, bool upper_copy) {
    const double lambda = column_angle(j);
    Vec3 p = on_section(ys[static_cast<std::size_t>(r)], lambda) + offset.at(ys[static_cast<std::size_t>(r)], lambda);
    p.y += lid_lift(j, p.y, upper_copy);
    for (int e = 0; e < 2; ++e) {  // the lids lie on a sphere just outside the eyeball: pushed forward
      const Vec3 c = eyeball_centre(e);
      const double across = (p.x - c.x) * (p.x - c.x) + (p.y - c.y) * (p.y - c.y);
      if (length(p - c) < kLidRadius && across < kLidRadius * kLidRadius)
        p.z = c.z + std::sqrt(kLidRadius * kLidRadius - across);
    }
    const std::uint32_t index = mesh.add(p, side_of(p, r, upper_copy));
    const int e = eye_of_column(j);
    if (e >= 0 && std::abs(ys[static_cast<std::size_t>(r)] - kEyeRow) <= 12) lids.push_back({index, e});
    return index;
  };

  // The grid, with a second (upper) vertex where a row is an opening.
  std::vector<std::uint32_t> grid(static_cast<std::size_t>(rows * kColumns));
  std::vector<std::uint32_t> upper(static_cast<std::size_t>(rows * kColumns));
  auto inside = [](const Opening& o, int r, int j) { return r == o.row && j > o.first && j < o.last; };
  for (int r = 0; r < rows; ++r)
    for (int j = 0; j < kColumns; ++j) {
      const std::size_t k = static_cast<std::size_t>(r * kColumns + j);
      grid[k] = upper[k] = place(r, j, false);
      if (inside(mouth, r, j) || inside(eyes[0], r, j) || inside(eyes[1], r, j)) upper[k] = place(r, j, true);
    }
  const std::uint32_t bottom = mesh.add(on_section(-114, 0), Side::any);
  const std::uint32_t top = mesh.add(on_section(122, 0), Side::any);

  auto material_of = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    const Vec3 m = (1.0 / 3) * (mesh.positions[a] + mesh.positions[b] + mesh.positions[c]);
    if (inside_lips(m)) return Material::lips;
    return is_hair(m) ? Material::hair : Material::skin;
  };
  auto tri = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) { mesh.triangle(material_of(a, b, c), a, b, c); };
  auto at = [&](const std::vector<std::uint32_t>& v, int r, int j) {
    return v[static_cast<std::size_t>(r * kColumns + (j + kColumns) % kColumns)];
  };
  for (int r = 0; r + 1 < rows; ++r)
    for (int j = 0; j < kColumns; ++j) {
      // The row below a quad uses the upper vertices of an opening; the row above the lower ones.
      const std::uint32_t a = at(upper, r, j), b = at(upper, r, j + 1), c = at(grid, r + 1, j + 1),
                          d = at(grid, r + 1, j);
      tri(a, b, c);
      tri(a, c, d);
    }
  for (int j = 0; j < kColumns; ++j) {
    tri(at(grid, 0, j + 1), at(grid, 0, j), bottom);
    tri(at(upper, rows - 1, j), at(upper, rows - 1, j + 1), top);
  }

  // The pockets. A loop around an opening: the lower side left to right, then the upper side back.
  auto loop_of = [&](const Opening& o) {
    std::vector<std::uint32_t> loop;
    for (int j = o.first; j <= o.last; ++j) loop.push_back(at(grid, o.row, j));
    for (int j = o.last - 1; j > o.first; --j) loop.push_back(at(upper, o.row, j));
    return loop;
  };
  auto strip = [&](Material m, const std::vector<std::uint32_t>& from, const std::vector<std::uint32_t>& to) {
    for (std::size_t i = 0; i < from.size(); ++i) {
      const std::size_t n = (i + 1) % from.size();
      mesh.triangle(m, from[i], from[n], to[n]);
      mesh.triangle(m, from[i], to[n], to[i]);
    }
  };
  auto fan = [&](Material m, const std::vector<std::uint32_t>& from, std::uint32_t apex) {
    for (std::size_t i = 0; i < from.size(); ++i) mesh.triangle(m, from[i], from[(i + 1) % from.size()], apex);
  };
  for (int e = 0; e < 2; ++e) {
    const std::uint32_t apex = mesh.add(eyeball_centre(e), Side::any);
    fan(Material::mouth, loop_of(eyes[e]), apex);
  }
  // The mouth's inside: three rings going back and opening up and down, then a point at the back.
  const std::vector<std::uint32_t> slit = loop_of(mouth);
  const double half_width = face::neutral(P::lip_l_corner_o).x;
  struct Ring {
    double narrow, open, back;
  };
  constexpr Ring kRings[] = {{0.95, 6, 5}, {0.85, 11, 13}, {0.6, 9, 24}};
  std::vector<std::uint32_t> previous = slit;
  for (std::size_t k = 0; k < std::size(kRings); ++k) {
    std::vector<std::uint32_t> ring;
    for (std::size_t i = 0; i < slit.size(); ++i) {
      const Vec3 s = mesh.positions[slit[i]];
      const Side side = mesh.sides[slit[i]];
      const double t = std::clamp(s.x / half_width, -1.0, 1.0);
      const bool corner = i == 0 || i == static_cast<std::size_t>(mouth.last - mouth.first);
      const double sign = corner ? 0 : (side == Side::mouth_upper ? 1 : -1);
      const Vec3 p{s.x * kRings[k].narrow, kMouthRow + sign * kRings[k].open * std::sqrt(1 - t * t),
                   s.z - kRings[k].back};
      ring.push_back(mesh.add(p, corner ? Side::any : side));
    }
    strip(k == 0 ? Material::lips : Material::mouth, previous, ring);
    previous = std::move(ring);
  }
  fan(Material::mouth, previous, mesh.add(Vec3{0, kMouthRow, face::neutral(P::lip_t_mid_i).z - 36}, Side::any));
}

}  // namespace fapc::head3d
