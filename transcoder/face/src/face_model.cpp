// The neutral face as data. The numbers are fapc's own, drawn for this renderer (a head about
// 230 mm from chin to crown); the layout follows the MPEG-4 feature point chart: eyes level,
// lips closed on a horizontal line at the height of their corners, eyelids tangent to the iris.
#include "fapc/face/face_model.hpp"

#include <array>
#include <cmath>

namespace fapc::face {

namespace {

constexpr std::array<FacePoint, kPointCount> kPoints{{
    {P::chin_bottom, "2.1", "bottom of the chin", {0, -108, 22}},
    {P::lip_t_mid_i, "2.2", "middle of the top inner lip", {0, -66, 36}},
    {P::lip_b_mid_i, "2.3", "middle of the bottom inner lip", {0, -66, 36}},
    {P::lip_l_corner_i, "2.4", "left inner lip corner", {21, -66, 29}},
    {P::lip_r_corner_i, "2.5", "right inner lip corner", {-21, -66, 29}},
    {P::lip_t_lm_i, "2.6", "top inner lip, left midpoint", {11, -66, 34}},
    {P::lip_t_rm_i, "2.7", "top inner lip, right midpoint", {-11, -66, 34}},
    {P::lip_b_lm_i, "2.8", "bottom inner lip, left midpoint", {11, -66, 34}},
    {P::lip_b_rm_i, "2.9", "bottom inner lip, right midpoint", {-11, -66, 34}},
    {P::chin_boss, "2.10", "chin boss", {0, -95, 34}},
    {P::chin_l, "2.11", "chin, left corner", {25, -100, 22}},
    {P::chin_r, "2.12", "chin, right corner", {-25, -100, 22}},
    {P::jaw_angle_l, "2.13", "left corner of the jaw bone", {62, -72, -18}},
    {P::jaw_angle_r, "2.14", "right corner of the jaw bone", {-62, -72, -18}},
    {P::lid_t_l, "3.1", "middle of the top left eyelid", {32, 5.5, 32}},
    {P::lid_t_r, "3.2", "middle of the top right eyelid", {-32, 5.5, 32}},
    {P::lid_b_l, "3.3", "middle of the bottom left eyelid", {32, -5.5, 32}},
    {P::lid_b_r, "3.4", "middle of the bottom right eyelid", {-32, -5.5, 32}},
    {P::pupil_l, "3.5", "centre of the left pupil", {32, 0, 33}},
    {P::pupil_r, "3.6", "centre of the right pupil", {-32, 0, 33}},
    {P::eye_l_outer, "", "outer corner of the left eye", {46, 0.5, 26}},
    {P::eye_l_inner, "", "inner corner of the left eye", {19, -0.5, 29}},
    {P::eye_r_outer, "", "outer corner of the right eye", {-46, 0.5, 26}},
    {P::eye_r_inner, "", "inner corner of the right eye", {-19, -0.5, 29}},
    {P::brow_l_inner, "4.1", "inner end of the left eyebrow", {14, 17, 38}},
    {P::brow_r_inner, "4.2", "inner end of the right eyebrow", {-14, 17, 38}},
    {P::brow_l_mid, "4.3", "middle of the left eyebrow", {32, 22, 36}},
    {P::brow_r_mid, "4.4", "middle of the right eyebrow", {-32, 22, 36}},
    {P::brow_l_outer, "4.5", "outer end of the left eyebrow", {49, 17, 27}},
    {P::brow_r_outer, "4.6", "outer end of the right eyebrow", {-49, 17, 27}},
    {P::cheek_l_side, "5.1", "left cheek, side of the face", {61, -40, 6}},
    {P::cheek_r_side, "5.2", "right cheek, side of the face", {-61, -40, 6}},
    {P::cheek_l, "5.3", "left cheek bone", {36, -28, 30}},
    {P::cheek_r, "5.4", "right cheek bone", {-36, -28, 30}},
    {P::cheek_l_upper, "", "side of the face at eye level, left", {63, -6, -6}},
    {P::cheek_r_upper, "", "side of the face at eye level, right", {-63, -6, -6}},
    {P::tongue_tip, "6.1", "tip of the tongue", {0, -68, 27}},
    {P::tongue_body, "6.2", "middle of the tongue", {0, -69, 12}},
    {P::spine_top, "7.1", "top of the spine: centre of head rotation", {0, -25, -40}},
    {P::lip_t_mid_o, "8.1", "middle of the top outer lip", {0, -58, 39}},
    {P::lip_b_mid_o, "8.2", "middle of the bottom outer lip", {0, -75, 37}},
    {P::lip_l_corner_o, "8.3", "left outer lip corner", {25, -66, 27}},
    {P::lip_r_corner_o, "8.4", "right outer lip corner", {-25, -66, 27}},
    {P::lip_t_lm_o, "8.5", "top outer lip, left midpoint", {13, -59, 36}},
    {P::lip_t_rm_o, "8.6", "top outer lip, right midpoint", {-13, -59, 36}},
    {P::lip_b_lm_o, "8.7", "bottom outer lip, left midpoint", {13, -73, 35}},
    {P::lip_b_rm_o, "8.8", "bottom outer lip, right midpoint", {-13, -73, 35}},
    {P::nose_l, "9.1", "left side of the nose", {13, -42, 36}},
    {P::nose_r, "9.2", "right side of the nose", {-13, -42, 36}},
    {P::nose_tip, "9.3", "tip of the nose", {0, -36, 54}},
    {P::nose_base, "9.15", "bottom of the nose, between the nostrils", {0, -46, 44}},
    {P::nose_bridge, "", "bridge of the nose between the eyes", {0, 2, 40}},
    {P::ear_l_top, "10.1", "top of the left ear", {75, 14, -22}},
    {P::ear_r_top, "10.2", "top of the right ear", {-75, 14, -22}},
    {P::ear_l_back, "10.3", "back of the left ear", {85, -6, -32}},
    {P::ear_r_back, "10.4", "back of the right ear", {-85, -6, -32}},
    {P::ear_l_lobe, "", "left ear lobe", {76, -32, -22}},
    {P::ear_r_lobe, "", "right ear lobe", {-76, -32, -22}},
    {P::ear_l_front, "", "front of the left ear", {73, -8, -14}},
    {P::ear_r_front, "", "front of the right ear", {-73, -8, -14}},
    {P::hairline, "11.1", "middle of the hairline", {0, 66, 28}},
    {P::head_top, "11.4", "top of the head", {0, 120, -20}},
    {P::teeth_t_l, "", "upper teeth, left end of the biting edge", {15, -67, 31}},
    {P::teeth_t_r, "", "upper teeth, right end of the biting edge", {-15, -67, 31}},
    {P::teeth_b_l, "", "lower teeth, left end of the biting edge", {14, -66, 30}},
    {P::teeth_b_r, "", "lower teeth, right end of the biting edge", {-14, -66, 30}},
}};

constexpr bool ordered() {
  for (int i = 0; i < kPointCount; ++i)
    if (static_cast<int>(kPoints[static_cast<std::size_t>(i)].id) != i) return false;
  return true;
}
static_assert(ordered(), "kPoints must list the points in the order of enum P");

const Ellipsoid kSkull{{0, 18, -18}, {74, 102, 88}};
const Ellipsoid kHair{{0, 30, -30}, {80, 96, 92}};

}  // namespace

std::span<const FacePoint> face_points() { return kPoints; }

std::optional<P> point_by_label(std::string_view label) {
  for (const FacePoint& p : kPoints)
    if (!p.label.empty() && p.label == label) return p.id;
  return std::nullopt;
}

const Ellipsoid& skull() { return kSkull; }
const Ellipsoid& hair() { return kHair; }

const Fapus& fapus() {
  static const Fapus units{
      neutral(P::lid_t_l).y - neutral(P::lid_b_l).y,
      neutral(P::pupil_l).x - neutral(P::pupil_r).x,
      neutral(P::pupil_l).y - neutral(P::nose_base).y,
      neutral(P::nose_base).y - neutral(P::lip_t_mid_i).y,
      neutral(P::lip_l_corner_o).x - neutral(P::lip_r_corner_o).x,
  };
  return units;
}

double Fapus::unit(Fapu u) const {
  switch (u) {
    case Fapu::irisd:
      return irisd0 / 1024;
    case Fapu::es:
      return es0 / 1024;
    case Fapu::ens:
      return ens0 / 1024;
    case Fapu::mns:
      return mns0 / 1024;
    case Fapu::mw:
      return mw0 / 1024;
    case Fapu::au:
      return 1e-5;
    case Fapu::none:
      return 0;
  }
  return 0;
}

}  // namespace fapc::face
