// The FAPs as morph targets of the 3D head, and a FAP sequence as target weights and rotations
// per frame. A target is the head's displacement at 1024 units of its FAP (one FAPU reference
// distance: MNS0, MW0, ES0, ENS0 or IRISD0; docs/render.md says why not one unit), so a frame's
// weight is value / 1024. Visemes and expressions (FAP 1 and 2) are targets made of their
// displacement sets, the same sets the 2D face uses. Head (48-50) and eyeball (23-26) rotations
// are not morphs: they turn the head's and the eyes' nodes.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "fapc/codec/fap_sequence.hpp"
#include "fapc/face/face_track.hpp"
#include "fapc/head3d/head_mesh.hpp"

namespace fapc::head3d {

inline constexpr double kTargetUnits = 1024;  // FAP units a target stands for

struct MorphTarget {
  std::string name;                     // the FAP's standard name ("open_jaw"), "viseme_PP", "expression_joy"
  int fap = 0;                          // 3..68 for a FAP's target; 0 for a viseme's or an expression's
  int viseme = 0;                       // 1..14
  int expression = 0;                   // 1..6
  std::vector<std::uint32_t> vertices;  // the vertices it moves, ascending
  std::vector<Vec3> displacements;      // millimetres, one per entry of `vertices`
};

// Every FAP that translates a point of the face (docs/render.md lists which do not), then the 14
// visemes, then the 6 expressions. Built once.
const std::vector<MorphTarget>& morph_targets();

// A quaternion (x, y, z, w), as glTF writes rotations.
using Quaternion = std::array<double, 4>;

struct HeadFrame {
  std::vector<double> weights;  // one per morph target
  Quaternion head;              // about 7.1: R = Ry(yaw) Rx(pitch) Rz(roll), FAPs 49, 48, 50
  Quaternion eyes[2];           // left, right, about each eyeball's centre: Ry(yaw) Rx(pitch)
  // The face's FAP values at this frame: the low-level values plus the viseme's and expression's
  // displacement sets, lip pairs applied (what the weights above add up to), rotations as held.
  face::FapValues faps{};
};

// The frames of a sequence on its grid (frame 0 .. last number), in order, every FAP held from
// the last frame that carried it, as fapc::face::FaceTrack holds them; `visit` sees each once (a
// long sequence is never held whole).
void for_each_head_frame(const FapSequence& sequence, const std::function<void(const HeadFrame&)>& visit);
std::vector<HeadFrame> head_frames(const FapSequence& sequence);  // all of them, for tests

// The head's vertex positions (millimetres, face coordinates, head upright) for one frame's
// weights: neutral + sum of weight x target. What an importer computes; the tests use it.
std::vector<Vec3> morphed_positions(const std::vector<double>& weights);

}  // namespace fapc::head3d
