// The face drawn with cairo. Every contour is a Catmull-Rom curve through its projected points
// (turned into cubic Beziers); parts are drawn far to near by the depth of a reference point after
// the head's rotation, and a part whose surface faces away from the viewer fades out.
#include "fapc/face/renderer.hpp"

#include <cairo.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "fapc/face/face_pose.hpp"
#include "stroke_text.hpp"

namespace fapc::face {

namespace {

struct Rgb {
  double r, g, b;
};
constexpr Rgb kBackground{0.87, 0.90, 0.93};
constexpr Rgb kSkin{0.95, 0.78, 0.65};
constexpr Rgb kSkinLine{0.66, 0.45, 0.35};
constexpr Rgb kHair{0.33, 0.22, 0.15};
constexpr Rgb kNeck{0.90, 0.72, 0.60};
constexpr Rgb kLips{0.76, 0.38, 0.38};
constexpr Rgb kMouth{0.29, 0.08, 0.09};
constexpr Rgb kTeeth{0.97, 0.96, 0.93};
constexpr Rgb kTongue{0.82, 0.42, 0.44};
constexpr Rgb kSclera{0.98, 0.98, 0.97};
constexpr Rgb kIris{0.29, 0.48, 0.63};
constexpr Rgb kPupil{0.05, 0.05, 0.06};
constexpr Rgb kBrow{0.30, 0.19, 0.12};
constexpr Rgb kLid{0.28, 0.17, 0.12};
constexpr Rgb kNostril{0.55, 0.32, 0.25};

struct Pt {
  double x, y;
};

// Samples of an ellipsoid's surface, for the framing radius.
std::vector<Vec3> ellipsoid_samples(const Ellipsoid& e) {
  std::vector<Vec3> out;
  for (int i = 0; i <= 24; ++i)
    for (int j = 0; j < 48; ++j) {
      const double theta = M_PI * i / 24, phi = 2 * M_PI * j / 48;
      out.push_back(e.centre + Vec3{e.radii.x * std::sin(theta) * std::cos(phi), e.radii.y * std::cos(theta),
                                    e.radii.z * std::sin(theta) * std::sin(phi)});
    }
  return out;
}

double length(Vec3 v) { return std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z); }

void set(cairo_t* cr, Rgb c, double alpha = 1) { cairo_set_source_rgba(cr, c.r, c.g, c.b, alpha); }

// A smooth curve through the points (Catmull-Rom, as cubic Beziers); closed or open.
void curve(cairo_t* cr, const std::vector<Pt>& p, bool closed) {
  const std::size_t n = p.size();
  if (n < 2) return;
  auto at = [&](std::ptrdiff_t i) -> const Pt& {
    if (closed) return p[static_cast<std::size_t>((i % std::ptrdiff_t(n) + std::ptrdiff_t(n)) % std::ptrdiff_t(n))];
    return p[static_cast<std::size_t>(std::clamp<std::ptrdiff_t>(i, 0, std::ptrdiff_t(n) - 1))];
  };
  cairo_move_to(cr, p[0].x, p[0].y);
  const std::ptrdiff_t segments = closed ? std::ptrdiff_t(n) : std::ptrdiff_t(n) - 1;
  for (std::ptrdiff_t i = 0; i < segments; ++i) {
    const Pt &p0 = at(i - 1), &p1 = at(i), &p2 = at(i + 1), &p3 = at(i + 2);
    cairo_curve_to(cr, p1.x + (p2.x - p0.x) / 6, p1.y + (p2.y - p0.y) / 6, p2.x - (p3.x - p1.x) / 6,
                   p2.y - (p3.y - p1.y) / 6, p2.x, p2.y);
  }
  if (closed) cairo_close_path(cr);
}

// A quadratic arc from a to b that passes through m at its middle (an eyelid through its corners).
void arc_through(cairo_t* cr, Pt a, Pt m, Pt b, bool move) {
  const Pt c{2 * m.x - (a.x + b.x) / 2, 2 * m.y - (a.y + b.y) / 2};
  if (move) cairo_move_to(cr, a.x, a.y);
  cairo_curve_to(cr, a.x + 2.0 / 3 * (c.x - a.x), a.y + 2.0 / 3 * (c.y - a.y), b.x + 2.0 / 3 * (c.x - b.x),
                 b.y + 2.0 / 3 * (c.y - b.y), b.x, b.y);
}

}  // namespace

double framing_radius() {
  static const double radius = [] {
    const Vec3 pivot = neutral(P::spine_top);
    double r = 0;
    for (const FacePoint& p : face_points()) r = std::max(r, length(p.neutral - pivot));
    for (const Ellipsoid* e : {&skull(), &hair()})
      for (const Vec3& s : ellipsoid_samples(*e)) r = std::max(r, length(s - pivot));
    return r * 1.03;  // a margin for the outline's stroke
  }();
  return radius;
}

struct FaceRenderer::State {
  Image image;
  cairo_surface_t* surface = nullptr;
  cairo_t* cr = nullptr;
  double scale = 1, cx = 0, cy = 0;
  Vec3 pivot;
  FacePose pose;
  bool points = false;

  Pt at(Vec3 v) const { return {cx + scale * (v.x - pivot.x), cy - scale * (v.y - pivot.y)}; }
  Pt at(P p) const { return at(pose.at(p)); }
  std::vector<Pt> at(std::initializer_list<P> ps) const {
    std::vector<Pt> out;
    out.reserve(ps.size());
    for (P p : ps) out.push_back(at(p));
    return out;
  }

  void ellipsoid(const Ellipsoid& e, Rgb fill, bool outline);
  void outline_and_fill(Rgb fill);
  void neck();
  void skin();
  void ear(bool left);
  void brow(bool left);
  void eye(bool left);
  void nose();
  void mouth();
  void cheek(bool left);
  void draw_all();
  void feature_points();
};

// Points on the far side of the head (facing away after the turn) are left out.
void FaceRenderer::State::feature_points() {
  const double h = std::max(6.0, 4.5 * scale);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  for (const FacePoint& p : face_points()) {
    if (p.id == P::spine_top) continue;  // inside the neck
    const Vec3 outward = p.neutral - Vec3{0, p.neutral.y, skull().centre.z};
    if (pose.turn_direction(outward).z < -5) continue;
    const Pt c = at(p.id);
    const bool standard = !p.label.empty();
    if (standard)
      cairo_set_source_rgb(cr, 0.85, 0.1, 0.1);
    else
      cairo_set_source_rgb(cr, 0.45, 0.45, 0.5);
    cairo_arc(cr, c.x, c.y, std::max(1.5, 0.9 * scale), 0, 2 * M_PI);
    cairo_fill(cr);
    if (!standard) continue;
    // Labels of left points to the right of the dot, right points to the left.
    const double width = stroke_text(cr, p.label, 0, -1000, h) - 0;
    cairo_new_path(cr);
    const double x = p.neutral.x >= 0 ? c.x + 0.4 * h : c.x - 0.4 * h - width;
    cairo_set_line_width(cr, std::max(1.0, h / 7));
    stroke_text(cr, p.label, x, c.y - h - 1, h);
    cairo_stroke(cr);
  }
}

// The outline of a turned ellipsoid seen along z: the 2x2 upper block of R D^2 R^T is the shape
// matrix of its orthographic shadow, an ellipse.
void FaceRenderer::State::ellipsoid(const Ellipsoid& e, Rgb fill, bool outline) {
  const Mat3& r = pose.head;
  const double d[3] = {e.radii.x * e.radii.x, e.radii.y * e.radii.y, e.radii.z * e.radii.z};
  double a = 0, b = 0, c = 0;  // [[a b][b c]]
  for (int k = 0; k < 3; ++k) {
    a += r.m[0][k] * r.m[0][k] * d[k];
    b += r.m[0][k] * r.m[1][k] * d[k];
    c += r.m[1][k] * r.m[1][k] * d[k];
  }
  const double mean = (a + c) / 2, spread = std::sqrt(std::max(0.0, (a - c) * (a - c) / 4 + b * b));
  const double major = std::sqrt(mean + spread), minor = std::sqrt(std::max(0.0, mean - spread));
  const double angle = 0.5 * std::atan2(2 * b, a - c);  // of the major axis, in face x/y
  const Pt centre = at(pose.turn(e.centre));
  cairo_save(cr);
  cairo_translate(cr, centre.x, centre.y);
  cairo_rotate(cr, -angle);  // screen y points down
  cairo_scale(cr, major * scale, std::max(minor, 1e-3) * scale);
  cairo_arc(cr, 0, 0, 1, 0, 2 * M_PI);
  cairo_restore(cr);
  if (outline) {
    outline_and_fill(fill);
    return;
  }
  set(cr, fill);
  cairo_fill(cr);
}

// The current path with the skin's outline colour round it, then filled.
void FaceRenderer::State::outline_and_fill(Rgb fill) {
  set(cr, kSkinLine);
  cairo_set_line_width(cr, 1.6 * scale);
  cairo_stroke_preserve(cr);
  set(cr, fill);
  cairo_fill(cr);
}

// The neck stays with the body: it does not turn with the head.
void FaceRenderer::State::neck() {
  const std::vector<Pt> p{at(Vec3{34, -40, -40}), at(Vec3{40, -220, -40}), at(Vec3{-40, -220, -40}),
                          at(Vec3{-34, -40, -40})};
  cairo_move_to(cr, p[0].x, p[0].y);
  for (std::size_t i = 1; i < p.size(); ++i) cairo_line_to(cr, p[i].x, p[i].y);
  cairo_close_path(cr);
  outline_and_fill(kNeck);
}

// The points that shape the lower face, seen from any side: the jaw line, the chin and the lips.
constexpr P kLowerFace[] = {P::cheek_l_upper, P::cheek_l_side, P::jaw_angle_l, P::chin_l,
                            P::chin_bottom,   P::chin_r,       P::jaw_angle_r, P::cheek_r_side,
                            P::cheek_r_upper, P::chin_boss,    P::lip_b_mid_o, P::lip_t_mid_o};

// The convex hull of projected points, counter-clockwise on the screen (Andrew's monotone chain).
std::vector<Pt> convex_hull(std::vector<Pt> p) {
  std::sort(p.begin(), p.end(), [](const Pt& a, const Pt& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  if (p.size() < 3) return p;
  auto cross = [](const Pt& o, const Pt& a, const Pt& b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
  };
  std::vector<Pt> hull(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p[i]) <= 0) --k;
    hull[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, lower = k + 1; i > 0; --i) {
    while (k >= lower && cross(hull[k - 2], hull[k - 1], p[i - 1]) <= 0) --k;
    hull[k++] = p[i - 1];
  }
  hull.resize(k - 1);
  return hull;
}

// Skull and lower face: the outlines of both are stroked first and then both filled, so only the
// outer edge of their union keeps a line. The lower face is the smooth curve round the convex
// hull of its projected points, which stays a sensible jaw from the front, the side and below.
void FaceRenderer::State::skin() {
  std::vector<Pt> projected;
  for (P p : kLowerFace) projected.push_back(at(p));
  const std::vector<Pt> jaw = convex_hull(std::move(projected));
  set(cr, kSkinLine);
  cairo_set_line_width(cr, 3.2 * scale);
  curve(cr, jaw, true);
  cairo_stroke(cr);
  ellipsoid(skull(), kSkin, true);
  curve(cr, jaw, true);
  set(cr, kSkin);
  cairo_fill(cr);
  // The chin's crease under the lower lip follows the chin boss.
  const Pt boss = at(P::chin_boss);
  set(cr, kSkinLine, 0.35);
  cairo_set_line_width(cr, 0.8 * scale);
  cairo_move_to(cr, boss.x - 8 * scale, boss.y - 4 * scale);
  cairo_curve_to(cr, boss.x - 3 * scale, boss.y - 1 * scale, boss.x + 3 * scale, boss.y - 1 * scale, boss.x + 8 * scale,
                 boss.y - 4 * scale);
  cairo_stroke(cr);
}

void FaceRenderer::State::ear(bool left) {
  const std::vector<Pt> p = left ? at({P::ear_l_top, P::ear_l_back, P::ear_l_lobe, P::ear_l_front})
                                 : at({P::ear_r_top, P::ear_r_back, P::ear_r_lobe, P::ear_r_front});
  curve(cr, p, true);
  outline_and_fill(kSkin);
}

void FaceRenderer::State::brow(bool left) {
  const std::vector<Pt> p = left ? at({P::brow_l_outer, P::brow_l_mid, P::brow_l_inner})
                                 : at({P::brow_r_outer, P::brow_r_mid, P::brow_r_inner});
  curve(cr, p, false);
  set(cr, kBrow);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  cairo_set_line_width(cr, 4.5 * scale);
  cairo_stroke(cr);
}

void FaceRenderer::State::eye(bool left) {
  const Pt outer = at(left ? P::eye_l_outer : P::eye_r_outer);
  const Pt inner = at(left ? P::eye_l_inner : P::eye_r_inner);
  const Pt top = at(left ? P::lid_t_l : P::lid_t_r);
  const Pt bottom = at(left ? P::lid_b_l : P::lid_b_r);
  // The opening: the upper lid from the outer to the inner corner, the lower lid back.
  arc_through(cr, outer, top, inner, true);
  arc_through(cr, inner, bottom, outer, false);
  cairo_close_path(cr);
  set(cr, kSclera);
  cairo_fill_preserve(cr);
  cairo_save(cr);
  cairo_clip(cr);
  const EyePose& e = pose.eyes[left ? 0 : 1];
  const Pt c = at(e.iris_centre);
  // The iris and the pupil are discs facing along the gaze: seen along z, ellipses whose minor
  // axis lies along the gaze's projection, shortened by its z component.
  const double tilt = std::atan2(-e.gaze.y, e.gaze.x);
  const double squash = std::max(std::abs(e.gaze.z), 0.05);
  for (const auto& [radius, colour] : {std::pair{e.iris_radius, kIris}, std::pair{e.pupil_radius, kPupil}}) {
    cairo_save(cr);
    cairo_translate(cr, c.x, c.y);
    cairo_rotate(cr, tilt);
    cairo_scale(cr, squash, 1);
    cairo_arc(cr, 0, 0, radius * scale, 0, 2 * M_PI);
    cairo_restore(cr);
    set(cr, colour);
    cairo_fill(cr);
  }
  set(cr, Rgb{1, 1, 1}, 0.8);
  cairo_arc(cr, c.x + 1.4 * scale, c.y - 1.6 * scale, 0.9 * scale, 0, 2 * M_PI);
  cairo_fill(cr);
  cairo_restore(cr);
  // Lid lines: the upper lid heavier.
  cairo_new_path(cr);
  set(cr, kLid);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  cairo_set_line_width(cr, 1.3 * scale);
  arc_through(cr, outer, top, inner, true);
  cairo_stroke(cr);
  cairo_set_line_width(cr, 0.5 * scale);
  arc_through(cr, inner, bottom, outer, true);
  cairo_stroke(cr);
}

void FaceRenderer::State::nose() {
  const FacePose& q = pose;
  const Vec3 base = q.at(P::nose_base), l = q.at(P::nose_l), r = q.at(P::nose_r), tip = q.at(P::nose_tip);
  // The wings and the underside: from one side of the nose round under the tip to the other.
  const Vec3 under_l = 0.5 * (l + base) + 0.25 * (tip - base);
  const Vec3 under_r = 0.5 * (r + base) + 0.25 * (tip - base);
  curve(cr, {at(l), at(under_l), at(base), at(under_r), at(r)}, false);
  set(cr, kSkinLine);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  cairo_set_line_width(cr, 1.0 * scale);
  cairo_stroke(cr);
  // The bridge's side line, from between the eyes to beside the tip.
  const Vec3 bridge = q.at(P::nose_bridge);
  const Vec3 side = tip + 0.35 * (l - base);
  curve(cr, {at(bridge + Vec3{0, -6, 0}), at(0.5 * (bridge + side) + Vec3{0, 0, 0}), at(side)}, false);
  set(cr, kSkinLine, 0.55);
  cairo_set_line_width(cr, 0.8 * scale);
  cairo_stroke(cr);
  // Nostrils.
  for (const Vec3& wing : {l, r}) {
    const Pt n = at(0.5 * (wing + base) + Vec3{0, 1, 0});
    cairo_save(cr);
    cairo_translate(cr, n.x, n.y);
    cairo_scale(cr, 2.6 * scale, 1.3 * scale);
    cairo_arc(cr, 0, 0, 1, 0, 2 * M_PI);
    cairo_restore(cr);
    set(cr, kNostril);
    cairo_fill(cr);
  }
}

void FaceRenderer::State::mouth() {
  const std::vector<Pt> outer = at({P::lip_l_corner_o, P::lip_t_lm_o, P::lip_t_mid_o, P::lip_t_rm_o, P::lip_r_corner_o,
                                    P::lip_b_rm_o, P::lip_b_mid_o, P::lip_b_lm_o});
  const std::vector<Pt> inner = at({P::lip_l_corner_i, P::lip_t_lm_i, P::lip_t_mid_i, P::lip_t_rm_i, P::lip_r_corner_i,
                                    P::lip_b_rm_i, P::lip_b_mid_i, P::lip_b_lm_i});
  curve(cr, outer, true);
  set(cr, kLips);
  cairo_fill(cr);
  curve(cr, inner, true);
  set(cr, kMouth);
  cairo_fill_preserve(cr);
  cairo_save(cr);
  cairo_clip(cr);
  // Tongue, then teeth: the upper row hangs from the skull, the lower row rides on the jaw.
  const Pt tip = at(P::tongue_tip), body = at(P::tongue_body);
  cairo_save(cr);
  cairo_translate(cr, (tip.x + body.x) / 2, (tip.y + body.y) / 2 + 3 * scale);
  cairo_scale(cr, 16 * scale, 7 * scale);
  cairo_arc(cr, 0, 0, 1, 0, 2 * M_PI);
  cairo_restore(cr);
  set(cr, kTongue);
  cairo_fill(cr);
  const FacePose& q = pose;
  for (const auto& [l, r, up] :
       {std::tuple{P::teeth_t_l, P::teeth_t_r, 1.0}, std::tuple{P::teeth_b_l, P::teeth_b_r, -1.0}}) {
    const Vec3 a = q.local[static_cast<std::size_t>(l)], b = q.local[static_cast<std::size_t>(r)];
    const std::vector<Pt> band{at(q.turn(a)), at(q.turn(b)), at(q.turn(b + Vec3{0, 7 * up, -2})),
                               at(q.turn(a + Vec3{0, 7 * up, -2}))};
    cairo_move_to(cr, band[0].x, band[0].y);
    for (std::size_t i = 1; i < band.size(); ++i) cairo_line_to(cr, band[i].x, band[i].y);
    cairo_close_path(cr);
    set(cr, kTeeth);
    cairo_fill(cr);
  }
  cairo_restore(cr);
  // The line where the lips meet.
  curve(cr, inner, true);
  set(cr, kMouth, 0.9);
  cairo_set_line_width(cr, 0.7 * scale);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_stroke(cr);
}

void FaceRenderer::State::cheek(bool left) {
  const Pt c = at(left ? P::cheek_l : P::cheek_r);
  cairo_pattern_t* glow = cairo_pattern_create_radial(c.x, c.y, 0, c.x, c.y, 13 * scale);
  cairo_pattern_add_color_stop_rgba(glow, 0, 0.93, 0.55, 0.52, 0.35);
  cairo_pattern_add_color_stop_rgba(glow, 1, 0.93, 0.55, 0.52, 0);
  cairo_set_source(cr, glow);
  cairo_arc(cr, c.x, c.y, 13 * scale, 0, 2 * M_PI);
  cairo_fill(cr);
  cairo_pattern_destroy(glow);
}

void FaceRenderer::State::draw_all() {
  set(cr, kBackground);
  cairo_paint(cr);
  neck();

  // Parts with the upright position and outward normal of a reference point: after turning, the
  // depth of the point orders them and the normal says whether the part faces the viewer.
  enum class Part { hair, skin, ear_l, ear_r, brow_l, brow_r, eye_l, eye_r, nose, mouth, cheek_l, cheek_r };
  struct Item {
    Part part;
    Vec3 reference;
    Vec3 normal;  // {0,0,0}: always drawn fully
    double depth = 0;
    double alpha = 1;
  };
  const Vec3 sc = skull().centre;
  std::array<Item, 12> items{{
      {Part::hair, hair().centre + Vec3{0, 10, -80}, {}},
      {Part::skin, sc, {}},
      {Part::ear_l, {80, -6, -30}, {}},
      {Part::ear_r, {-80, -6, -30}, {}},
      {Part::brow_l, neutral(P::brow_l_mid), {0.3, 0.1, 1}},
      {Part::brow_r, neutral(P::brow_r_mid), {-0.3, 0.1, 1}},
      {Part::eye_l, neutral(P::pupil_l), {0.3, 0, 1}},
      {Part::eye_r, neutral(P::pupil_r), {-0.3, 0, 1}},
      {Part::nose, neutral(P::nose_tip), {0, 0, 1}},
      {Part::mouth, neutral(P::lip_t_mid_o), {0, -0.2, 1}},
      {Part::cheek_l, neutral(P::cheek_l), {0.6, 0, 0.8}},
      {Part::cheek_r, neutral(P::cheek_r), {-0.6, 0, 0.8}},
  }};
  for (Item& item : items) {
    item.depth = pose.turn(item.reference).z;
    if (item.normal.x != 0 || item.normal.y != 0 || item.normal.z != 0) {
      const Vec3 n = pose.turn_direction((1 / length(item.normal)) * item.normal);
      item.alpha = std::clamp(n.z / 0.25, 0.0, 1.0);  // fades out as it turns away
    }
  }
  std::stable_sort(items.begin(), items.end(), [](const Item& a, const Item& b) { return a.depth < b.depth; });
  for (const Item& item : items) {
    if (item.alpha <= 0) continue;
    if (item.alpha < 1) cairo_push_group(cr);
    switch (item.part) {
      case Part::hair:
        ellipsoid(hair(), kHair, false);
        break;
      case Part::skin:
        skin();
        break;
      case Part::ear_l:
        ear(true);
        break;
      case Part::ear_r:
        ear(false);
        break;
      case Part::brow_l:
        brow(true);
        break;
      case Part::brow_r:
        brow(false);
        break;
      case Part::eye_l:
        eye(true);
        break;
      case Part::eye_r:
        eye(false);
        break;
      case Part::nose:
        nose();
        break;
      case Part::mouth:
        mouth();
        break;
      case Part::cheek_l:
        cheek(true);
        break;
      case Part::cheek_r:
        cheek(false);
        break;
    }
    if (item.alpha < 1) {
      cairo_pop_group_to_source(cr);
      cairo_paint_with_alpha(cr, item.alpha);
    }
  }
}

FaceRenderer::FaceRenderer(int width, int height) : state_(std::make_unique<State>()) {
  State& s = *state_;
  s.image = Image(width, height);
  s.surface = cairo_image_surface_create_for_data(reinterpret_cast<unsigned char*>(s.image.pixels.data()),
                                                  CAIRO_FORMAT_ARGB32, width, height, width * 4);
  s.cr = cairo_create(s.surface);
  s.scale = std::min(width, height) / (2 * framing_radius());
  s.cx = width / 2.0;
  s.cy = height / 2.0;
  s.pivot = neutral(P::spine_top);
}

FaceRenderer::~FaceRenderer() {
  cairo_destroy(state_->cr);
  cairo_surface_destroy(state_->surface);
}

const Image& FaceRenderer::render(const FapValues& values) {
  State& s = *state_;
  s.pose = pose_face(values);
  cairo_save(s.cr);
  s.draw_all();
  if (s.points) s.feature_points();
  cairo_restore(s.cr);
  cairo_surface_flush(s.surface);
  return s.image;
}

void FaceRenderer::show_feature_points(bool show) { state_->points = show; }

int FaceRenderer::width() const { return state_->image.width; }
int FaceRenderer::height() const { return state_->image.height; }
double FaceRenderer::scale() const { return state_->scale; }
double FaceRenderer::screen_x(double face_x) const { return state_->cx + state_->scale * (face_x - state_->pivot.x); }
double FaceRenderer::screen_y(double face_y) const { return state_->cy - state_->scale * (face_y - state_->pivot.y); }

}  // namespace fapc::face
