// The neutral face fapc draws: MPEG-4 feature points of groups 2-11 in 3D (our own numbers, in
// millimetres, face coordinates of fapc/codec/fap_motion.hpp), the few contour points the drawing
// adds between them, and the FAPUs measured on it as the standard defines them. docs/render.md
// shows the face and lists the points.
#pragma once

#include <array>
#include <optional>
#include <span>
#include <string_view>

#include "fapc/codec/fap_table.hpp"

namespace fapc::face {

struct Vec3 {
  double x = 0, y = 0, z = 0;
  friend Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
  friend Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
  friend Vec3 operator*(double s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
};

// Every point of the face, by index. The standard's feature points keep their numbers in the
// comments and in `FacePoint::label`; the contour points the drawing adds say what they are.
enum class P : int {
  chin_bottom,     // 2.1
  lip_t_mid_i,     // 2.2
  lip_b_mid_i,     // 2.3
  lip_l_corner_i,  // 2.4
  lip_r_corner_i,  // 2.5
  lip_t_lm_i,      // 2.6
  lip_t_rm_i,      // 2.7
  lip_b_lm_i,      // 2.8
  lip_b_rm_i,      // 2.9
  chin_boss,       // 2.10
  chin_l,          // 2.11
  chin_r,          // 2.12
  jaw_angle_l,     // 2.13
  jaw_angle_r,     // 2.14
  lid_t_l,         // 3.1
  lid_t_r,         // 3.2
  lid_b_l,         // 3.3
  lid_b_r,         // 3.4
  pupil_l,         // 3.5
  pupil_r,         // 3.6
  eye_l_outer,     // contour: outer corner of the left eye
  eye_l_inner,     // contour: inner corner of the left eye
  eye_r_outer,     // contour
  eye_r_inner,     // contour
  brow_l_inner,    // 4.1
  brow_r_inner,    // 4.2
  brow_l_mid,      // 4.3
  brow_r_mid,      // 4.4
  brow_l_outer,    // 4.5
  brow_r_outer,    // 4.6
  cheek_l_side,    // 5.1
  cheek_r_side,    // 5.2
  cheek_l,         // 5.3
  cheek_r,         // 5.4
  cheek_l_upper,   // contour: side of the face at eye level, left
  cheek_r_upper,   // contour
  tongue_tip,      // 6.1
  tongue_body,     // 6.2
  spine_top,       // 7.1: the head turns about it
  lip_t_mid_o,     // 8.1
  lip_b_mid_o,     // 8.2
  lip_l_corner_o,  // 8.3
  lip_r_corner_o,  // 8.4
  lip_t_lm_o,      // 8.5
  lip_t_rm_o,      // 8.6
  lip_b_lm_o,      // 8.7
  lip_b_rm_o,      // 8.8
  nose_l,          // 9.1
  nose_r,          // 9.2
  nose_tip,        // 9.3
  nose_base,       // 9.15
  nose_bridge,     // contour: between the eyes
  ear_l_top,       // 10.1
  ear_r_top,       // 10.2
  ear_l_back,      // 10.3
  ear_r_back,      // 10.4
  ear_l_lobe,      // contour
  ear_r_lobe,      // contour
  ear_l_front,     // contour
  ear_r_front,     // contour
  hairline,        // 11.1
  head_top,        // 11.4
  teeth_t_l,       // contour: upper teeth, left end of their lower edge
  teeth_t_r,       // contour
  teeth_b_l,       // contour: lower teeth, left end of their upper edge
  teeth_b_r,       // contour
  count
};
inline constexpr int kPointCount = static_cast<int>(P::count);

struct FacePoint {
  P id;
  std::string_view label;  // "2.1" for a standard feature point, "" for a contour point
  std::string_view name;   // what it is
  Vec3 neutral;            // position on the neutral face, millimetres
};

// All points, indexed by P.
std::span<const FacePoint> face_points();
inline const Vec3& neutral(P p) { return face_points()[static_cast<std::size_t>(p)].neutral; }

// The standard feature point named "2.1", or nothing.
std::optional<P> point_by_label(std::string_view label);

// An ellipsoid of the head (skull, hair): centre and radii in face coordinates.
struct Ellipsoid {
  Vec3 centre;
  Vec3 radii;
};
const Ellipsoid& skull();
const Ellipsoid& hair();

// Eyeball radius (the pupil point 3.5/3.6 is on its front), millimetres.
inline constexpr double kEyeballRadius = 12.0;

// FAPUs of the neutral face in millimetres per FAP unit (AU in radians per unit), measured as the
// standard defines them: IRISD0 = 3.1.y - 3.3.y, ES0 = 3.5.x - 3.6.x, ENS0 = 3.5.y - 9.15.y,
// MNS0 = 9.15.y - 2.2.y, MW0 = 8.3.x - 8.4.x, each divided by 1024; AU = 1e-5 rad.
struct Fapus {
  double irisd0, es0, ens0, mns0, mw0;  // the distances themselves, millimetres
  double unit(Fapu u) const;            // one FAP unit of u
};
const Fapus& fapus();

}  // namespace fapc::face
