#include "fapc/face/face_pose.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "fapc/codec/fap_motion.hpp"

namespace fapc::face {

Mat3 Mat3::operator*(const Mat3& o) const {
  Mat3 r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      r.m[i][j] = 0;
      for (int k = 0; k < 3; ++k) r.m[i][j] += m[i][k] * o.m[k][j];
    }
  return r;
}

Mat3 rotation_x(double a) {
  const double c = std::cos(a), s = std::sin(a);
  return Mat3{{{1, 0, 0}, {0, c, -s}, {0, s, c}}};
}
Mat3 rotation_y(double a) {
  const double c = std::cos(a), s = std::sin(a);
  return Mat3{{{c, 0, s}, {0, 1, 0}, {-s, 0, c}}};
}
Mat3 rotation_z(double a) {
  const double c = std::cos(a), s = std::sin(a);
  return Mat3{{{c, -s, 0}, {s, c, 0}, {0, 0, 1}}};
}

namespace {

struct Follower {
  P point;
  double weight;
};

// The points that move with a translation FAP besides its own feature point (weight 1), and how
// much. The jaw carries the chin, the lower lip, the lower teeth and the tongue; lip midpoints
// follow their middle; a brow's points drag their neighbours; an ear moves as a whole.
std::vector<Follower> followers(int fap) {
  switch (fap) {
    case 3:
    case 14:
    case 15:  // open_jaw, thrust_jaw, shift_jaw
      return {{P::chin_boss, 1},        {P::chin_l, 1},           {P::chin_r, 1},           {P::lip_b_mid_i, 1},
              {P::lip_b_lm_i, 1},       {P::lip_b_rm_i, 1},       {P::lip_b_mid_o, 1},      {P::lip_b_lm_o, 1},
              {P::lip_b_rm_o, 1},       {P::teeth_b_l, 1},        {P::teeth_b_r, 1},        {P::tongue_tip, 0.6},
              {P::tongue_body, 0.6},    {P::lip_l_corner_i, 0.5}, {P::lip_r_corner_i, 0.5}, {P::lip_l_corner_o, 0.5},
              {P::lip_r_corner_o, 0.5}, {P::jaw_angle_l, 0.25},   {P::jaw_angle_r, 0.25},   {P::cheek_l_side, 0.2},
              {P::cheek_r_side, 0.2}};
    case 4:
    case 17:
      return {{P::lip_t_lm_i, 0.6}, {P::lip_t_rm_i, 0.6}};
    case 5:
    case 16:
      return {{P::lip_b_lm_i, 0.6}, {P::lip_b_rm_i, 0.6}};
    case 6:
    case 12:
      return {{P::lip_t_lm_i, 0.4}, {P::lip_b_lm_i, 0.4}};
    case 7:
    case 13:
      return {{P::lip_t_rm_i, 0.4}, {P::lip_b_rm_i, 0.4}};
    case 18:
      return {{P::chin_bottom, 0.5}};
    case 31:
      return {{P::brow_l_mid, 0.3}};
    case 32:
      return {{P::brow_r_mid, 0.3}};
    case 33:
      return {{P::brow_l_inner, 0.3}, {P::brow_l_outer, 0.3}};
    case 34:
      return {{P::brow_r_inner, 0.3}, {P::brow_r_outer, 0.3}};
    case 35:
      return {{P::brow_l_mid, 0.3}};
    case 36:
      return {{P::brow_r_mid, 0.3}};
    case 37:
      return {{P::brow_l_mid, 0.5}, {P::brow_l_outer, 0.2}};
    case 38:
      return {{P::brow_r_mid, 0.5}, {P::brow_r_outer, 0.2}};
    case 39:
      return {{P::jaw_angle_l, 0.3}, {P::cheek_l, 0.3}};
    case 40:
      return {{P::jaw_angle_r, 0.3}, {P::cheek_r, 0.3}};
    case 41:
      return {{P::lid_b_l, 0.2}};
    case 42:
      return {{P::lid_b_r, 0.2}};
    case 46:
      return {{P::tongue_tip, 0.5}};
    case 51:
      return {{P::lip_t_lm_o, 0.6}, {P::lip_t_rm_o, 0.6}};
    case 52:
      return {{P::lip_b_lm_o, 0.6}, {P::lip_b_rm_o, 0.6}};
    case 53:
    case 59:
      return {{P::lip_t_lm_o, 0.4}, {P::lip_b_lm_o, 0.4}};
    case 54:
    case 60:
      return {{P::lip_t_rm_o, 0.4}, {P::lip_b_rm_o, 0.4}};
    case 63:
      return {{P::nose_base, 0.5}, {P::nose_l, 0.3}, {P::nose_r, 0.3}};
    case 64:
      return {{P::nose_base, 0.5}};
    case 65:
    case 67:
      return {{P::ear_l_top, 1}, {P::ear_l_back, 1}, {P::ear_l_lobe, 1}, {P::ear_l_front, 1}};
    case 66:
    case 68:
      return {{P::ear_r_top, 1}, {P::ear_r_back, 1}, {P::ear_r_lobe, 1}, {P::ear_r_front, 1}};
    default:
      return {};
  }
}

struct Influence {
  int fap;
  double mm_per_unit;
  Vec3 direction;
  std::vector<Follower> points;  // the feature point itself first
};

// Built once from the FAP table's motions and units.
const std::vector<Influence>& influences() {
  static const std::vector<Influence> table = [] {
    std::vector<Influence> out;
    for (int fap = 3; fap <= kFapCount; ++fap) {
      const FapMotion& motion = *fap_motion(fap);
      if (motion.action != FapAction::translation) continue;
      if (fap == 27 || fap == 28) continue;  // eyeball thrust: moves the eyeball (pose_eye)
      const std::optional<P> own = point_by_label(motion.feature_point);
      if (!own) continue;
      Influence in{fap,
                   fapus().unit(find_fap(fap)->unit),
                   Vec3{double(motion.direction[0]), double(motion.direction[1]), double(motion.direction[2])},
                   {{*own, 1}}};
      for (const Follower& f : followers(fap))
        if (f.point != *own) in.points.push_back(f);
      out.push_back(std::move(in));
    }
    return out;
  }();
  return table;
}

// Inner and outer lip FAPs that act on the same spot: when a frame drives only one of the pair,
// the other follows it, so a stream that animates only the inner (or outer) contour still moves
// the whole lip.
constexpr int kLipPairs[][2] = {{4, 51}, {5, 52},  {6, 53},  {7, 54},  {8, 55},
                                {9, 56}, {10, 57}, {11, 58}, {12, 59}, {13, 60}};

double fap(const FapValues& v, int number) { return v[static_cast<std::size_t>(number - 1)]; }

// Where a lid or lip pair crosses (top below bottom), both meet halfway: lids close, lips press.
void meet_if_crossed(FacePose& pose, P top, P bottom) {
  Vec3& t = pose.local[static_cast<std::size_t>(top)];
  Vec3& b = pose.local[static_cast<std::size_t>(bottom)];
  if (t.y < b.y) t.y = b.y = (t.y + b.y) / 2;
}

EyePose pose_eye(const FapValues& v, P pupil, int yaw_fap, int pitch_fap, int thrust_fap, int dilate_fap) {
  const double au = fapus().unit(Fapu::au);
  const Vec3 gaze = rotation_y(fap(v, yaw_fap) * au) * (rotation_x(fap(v, pitch_fap) * au) * Vec3{0, 0, 1});
  Vec3 centre = neutral(pupil) - Vec3{0, 0, kEyeballRadius};
  centre.z += fap(v, thrust_fap) * fapus().unit(Fapu::es);
  const double iris_radius = fapus().irisd0 / 2;
  const double pupil_diameter = fapus().irisd0 / 3 + fap(v, dilate_fap) * fapus().unit(Fapu::irisd);
  return EyePose{centre + kEyeballRadius * gaze, gaze, iris_radius,
                 std::clamp(pupil_diameter / 2, 0.3, iris_radius * 0.9)};
}

}  // namespace

FapValues with_lip_pairs(const FapValues& values) {
  FapValues v = values;
  for (const auto& pair : kLipPairs) {
    double& inner = v[static_cast<std::size_t>(pair[0] - 1)];
    double& outer = v[static_cast<std::size_t>(pair[1] - 1)];
    if (inner == 0)
      inner = outer;
    else if (outer == 0)
      outer = inner;
  }
  return v;
}

std::vector<PointMotion> point_motions(int fap) {
  for (const Influence& in : influences())
    if (in.fap == fap) {
      std::vector<PointMotion> out;
      for (const Follower& f : in.points) out.push_back({f.point, (in.mm_per_unit * f.weight) * in.direction});
      return out;
    }
  return {};
}

FacePose pose_face(const FapValues& values) {
  const FapValues v = with_lip_pairs(values);

  FacePose pose;
  for (int i = 0; i < kPointCount; ++i)
    pose.local[static_cast<std::size_t>(i)] = face_points()[static_cast<std::size_t>(i)].neutral;
  for (const Influence& in : influences()) {
    const double amount = fap(v, in.fap) * in.mm_per_unit;
    if (amount == 0) continue;
    for (const Follower& f : in.points)
      pose.local[static_cast<std::size_t>(f.point)] =
          pose.local[static_cast<std::size_t>(f.point)] + (amount * f.weight) * in.direction;
  }
  meet_if_crossed(pose, P::lid_t_l, P::lid_b_l);
  meet_if_crossed(pose, P::lid_t_r, P::lid_b_r);
  meet_if_crossed(pose, P::lip_t_mid_i, P::lip_b_mid_i);
  meet_if_crossed(pose, P::lip_t_lm_i, P::lip_b_lm_i);
  meet_if_crossed(pose, P::lip_t_rm_i, P::lip_b_rm_i);

  const double au = fapus().unit(Fapu::au);
  // Yaw, then pitch, then roll as seen from the body: R = Ry(yaw) Rx(pitch) Rz(roll).
  pose.head = rotation_y(fap(v, 49) * au) * rotation_x(fap(v, 48) * au) * rotation_z(fap(v, 50) * au);
  pose.pivot = neutral(P::spine_top);
  for (int i = 0; i < kPointCount; ++i)
    pose.points[static_cast<std::size_t>(i)] = pose.turn(pose.local[static_cast<std::size_t>(i)]);

  const EyePose eyes[2] = {pose_eye(v, P::pupil_l, 23, 25, 27, 29), pose_eye(v, P::pupil_r, 24, 26, 28, 30)};
  for (int e = 0; e < 2; ++e) {
    pose.eyes[e] = eyes[e];
    pose.eyes[e].iris_centre = pose.turn(eyes[e].iris_centre);
    pose.eyes[e].gaze = pose.turn_direction(eyes[e].gaze);
  }
  return pose;
}

}  // namespace fapc::face
