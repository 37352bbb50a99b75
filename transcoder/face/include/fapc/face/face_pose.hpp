// A face posed by one moment's FAP values: every point displaced by the FAPs that drive it (and
// those that follow it, by the rules of docs/render.md), then turned with the head about 7.1.
#pragma once

#include <array>
#include <vector>

#include "fapc/face/face_model.hpp"
#include "fapc/face/face_track.hpp"

namespace fapc::face {

struct Mat3 {
  double m[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  Vec3 operator*(Vec3 v) const {
    return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z, m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
            m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
  }
  Mat3 operator*(const Mat3& o) const;
};
// Right-hand rotations about the face axes.
Mat3 rotation_x(double radians);
Mat3 rotation_y(double radians);
Mat3 rotation_z(double radians);

struct EyePose {
  Vec3 iris_centre;     // after the head's rotation
  Vec3 gaze;            // unit normal of the iris disc, after the head's rotation
  double iris_radius;   // millimetres
  double pupil_radius;  // millimetres
};

struct FacePose {
  std::array<Vec3, kPointCount> points;  // face coordinates after displacement and head rotation
  std::array<Vec3, kPointCount> local;   // after displacement only (head upright)
  Mat3 head;                             // the head's rotation about 7.1
  EyePose eyes[2];                       // left, right
  Vec3 pivot;                            // 7.1
  // A point given in upright head coordinates, turned with the head.
  Vec3 turn(Vec3 upright) const { return pivot + head * (upright - pivot); }
  // A direction turned with the head.
  Vec3 turn_direction(Vec3 d) const { return head * d; }
  const Vec3& at(P p) const { return points[static_cast<std::size_t>(p)]; }
};

FacePose pose_face(const FapValues& values);

// Inner and outer lip FAPs that act on the same spot (4/51 ... 13/60): where a frame drives only
// one of a pair, the other takes its value (docs/render.md, "How FAPs move it").
FapValues with_lip_pairs(const FapValues& values);

// Where translation FAP `fap` moves the face: its own feature point first, then the points that
// follow it, each with its displacement per FAP unit in millimetres (direction x FAPU x the
// follower's weight). Empty for FAPs that are not translations of a point (1, 2, rotations,
// dilations, eyeball thrust). The 3D head (fapc::head3d) takes its morph targets from this.
struct PointMotion {
  P point;
  Vec3 mm_per_unit;
};
std::vector<PointMotion> point_motions(int fap);

}  // namespace fapc::face
