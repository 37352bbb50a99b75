#include "fapc/head3d/head_morphs.hpp"

#include <algorithm>
#include <cmath>

#include "fapc/codec/fap_table.hpp"
#include "fapc/face/face_pose.hpp"
#include "fapc/face/face_track.hpp"
#include "mesh_building.hpp"

namespace fapc::head3d {

namespace {

using face::FapValues;

// Displacements below this (millimetres) are left out of a target: a thousandth of a millimetre
// is far below what any renderer shows.
constexpr double kNegligible = 1e-3;

MorphTarget sparse(std::string name, const std::vector<Vec3>& dense) {
  MorphTarget t;
  t.name = std::move(name);
  for (std::size_t v = 0; v < dense.size(); ++v)
    if (length(dense[v]) > kNegligible) {
      t.vertices.push_back(static_cast<std::uint32_t>(v));
      t.displacements.push_back(dense[v]);
    }
  return t;
}

// FAP `fap`'s displacement of every vertex at kTargetUnits: each anchor moves as fapc::face moves
// the point it follows (times its weight), each vertex by the weighted sum of its anchors; a lid's
// vertices are then kept outside the eyeball.
std::vector<Vec3> fap_displacement(int fap) {
  const HeadMesh& mesh = head_mesh();
  std::vector<Vec3> anchor_moves(mesh.anchors.size());
  bool any = false;
  for (const face::PointMotion& m : face::point_motions(fap))
    for (std::size_t a = 0; a < mesh.anchors.size(); ++a)
      if (mesh.anchors[a].point == static_cast<int>(m.point)) {
        anchor_moves[a] = anchor_moves[a] + (kTargetUnits * mesh.anchors[a].weight) * m.mm_per_unit;
        any = true;
      }
  std::vector<Vec3> out(mesh.positions.size());
  if (!any) return out;
  for (std::size_t v = 0; v < out.size(); ++v) {
    const Binding& b = mesh.bindings[v];
    for (std::size_t k = 0; k < 4; ++k)
      if (b.anchor[k] >= 0) out[v] = out[v] + b.weight[k] * anchor_moves[static_cast<std::size_t>(b.anchor[k])];
  }
  for (const auto& [v, eye] : mesh.lid_vertices) {
    const Vec3 c = eyeball_centre(eye), moved = mesh.positions[v] + out[v];
    const double d = length(moved - c);
    if (length(out[v]) > 0 && d < kLidRadius && d > 0) out[v] = c + (kLidRadius / d) * (moved - c) - mesh.positions[v];
  }
  return out;
}

std::vector<MorphTarget> build() {
  std::vector<MorphTarget> targets;
  std::vector<std::vector<Vec3>> by_fap(kFapCount + 1);
  for (int fap = 3; fap <= kFapCount; ++fap) {
    if (face::point_motions(fap).empty()) continue;
    by_fap[static_cast<std::size_t>(fap)] = fap_displacement(fap);
    MorphTarget t = sparse(std::string(find_fap(fap)->name), by_fap[static_cast<std::size_t>(fap)]);
    t.fap = fap;
    targets.push_back(std::move(t));
  }
  // A viseme's or an expression's target: its displacement set's FAPs, each target times value/1024.
  auto of_set = [&](const FapValues& set) {
    std::vector<Vec3> dense(head_mesh().positions.size());
    for (int fap = 3; fap <= kFapCount; ++fap) {
      const double w = set[static_cast<std::size_t>(fap - 1)] / kTargetUnits;
      const std::vector<Vec3>& d = by_fap[static_cast<std::size_t>(fap)];
      if (w == 0 || d.empty()) continue;
      for (std::size_t v = 0; v < dense.size(); ++v) dense[v] = dense[v] + w * d[v];
    }
    return dense;
  };
  for (int v = 1; v <= 14; ++v) {
    MorphTarget t = sparse("viseme_" + std::string(viseme_name(v)), of_set(face::viseme_displacements(v)));
    t.viseme = v;
    targets.push_back(std::move(t));
  }
  for (int e = 1; e <= 6; ++e) {
    MorphTarget t = sparse("expression_" + std::string(expression_name(e)), of_set(face::expression_displacements(e)));
    t.expression = e;
    targets.push_back(std::move(t));
  }
  return targets;
}

Quaternion about(int axis, double radians) {
  Quaternion q{0, 0, 0, std::cos(radians / 2)};
  q[static_cast<std::size_t>(axis)] = std::sin(radians / 2);
  return q;
}

Quaternion operator*(const Quaternion& a, const Quaternion& b) {
  return {a[3] * b[0] + a[0] * b[3] + a[1] * b[2] - a[2] * b[1], a[3] * b[1] - a[0] * b[2] + a[1] * b[3] + a[2] * b[0],
          a[3] * b[2] + a[0] * b[1] - a[1] * b[0] + a[2] * b[3], a[3] * b[3] - a[0] * b[0] - a[1] * b[1] - a[2] * b[2]};
}

double value(const FapValues& v, int fap) { return v[static_cast<std::size_t>(fap - 1)]; }

HeadFrame frame_of(const FapValues& held, const VisemeFields& viseme, bool has_viseme,
                   const ExpressionFields& expression, bool has_expression) {
  const std::vector<MorphTarget>& targets = morph_targets();
  // The lip pairs act on the sum of the low-level values and the high-level sets, as on the 2D
  // face; the low-level weights take what the pairs add, so that the sum is the same.
  const FapValues high = face::high_level_values(viseme, has_viseme, expression, has_expression);
  FapValues total = held;
  for (std::size_t i = 0; i < total.size(); ++i) total[i] += high[i];
  const FapValues paired = face::with_lip_pairs(total);
  HeadFrame f;
  f.weights.reserve(targets.size());
  const double blend = std::clamp(viseme.blend, 0, 63) / 63.0;
  for (const MorphTarget& t : targets) {
    double w = 0;
    if (t.fap) {
      w = (value(paired, t.fap) - value(high, t.fap)) / kTargetUnits;
    } else if (t.viseme && has_viseme) {
      w = (viseme.select1 == t.viseme ? blend : 0) + (viseme.select2 == t.viseme ? 1 - blend : 0);
    } else if (t.expression && has_expression) {
      w = (expression.select1 == t.expression ? std::clamp(expression.intensity1, 0, 63) / 63.0 : 0) +
          (expression.select2 == t.expression ? std::clamp(expression.intensity2, 0, 63) / 63.0 : 0);
    }
    f.weights.push_back(w);
  }
  f.faps = paired;
  const double au = face::fapus().unit(Fapu::au);
  f.head = about(1, value(held, 49) * au) * about(0, value(held, 48) * au) * about(2, value(held, 50) * au);
  f.eyes[0] = about(1, value(held, 23) * au) * about(0, value(held, 25) * au);
  f.eyes[1] = about(1, value(held, 24) * au) * about(0, value(held, 26) * au);
  return f;
}

}  // namespace

const std::vector<MorphTarget>& morph_targets() {
  static const std::vector<MorphTarget> targets = build();
  return targets;
}

void for_each_head_frame(const FapSequence& sequence, const std::function<void(const HeadFrame&)>& visit) {
  FapValues held{};
  VisemeFields viseme;
  ExpressionFields expression;
  bool has_viseme = false, has_expression = false;
  std::int64_t next = 0;  // the next grid frame to show
  HeadFrame shown = frame_of(held, viseme, false, expression, false);
  bool pending = false;  // `shown` is frame next - 1 and not yet visited (a repeated number may replace it)
  for (const FapFrame& frame : sequence.frames) {
    if (frame.number < 0) continue;
    if (frame.number >= next) {
      if (pending) visit(shown);
      for (; next < frame.number; ++next) visit(shown);  // grid frames before this one hold
      next = frame.number + 1;
    }
    for (int fap = 3; fap <= kFapCount; ++fap)
      if (frame.has(fap)) held[static_cast<std::size_t>(fap - 1)] = frame.value(fap);
    if (frame.has(1)) viseme = frame.viseme, has_viseme = true;
    if (frame.has(2)) expression = frame.expression, has_expression = true;
    shown = frame_of(held, viseme, has_viseme, expression, has_expression);  // a repeated number replaces
    pending = true;
  }
  if (pending) visit(shown);
}

std::vector<HeadFrame> head_frames(const FapSequence& sequence) {
  std::vector<HeadFrame> frames;
  for_each_head_frame(sequence, [&](const HeadFrame& f) { frames.push_back(f); });
  return frames;
}

std::vector<Vec3> morphed_positions(const std::vector<double>& weights) {
  std::vector<Vec3> p = head_mesh().positions;
  const std::vector<MorphTarget>& targets = morph_targets();
  for (std::size_t t = 0; t < targets.size() && t < weights.size(); ++t)
    for (std::size_t i = 0; i < targets[t].vertices.size(); ++i)
      p[targets[t].vertices[i]] = p[targets[t].vertices[i]] + weights[t] * targets[t].displacements[i];
  return p;
}

}  // namespace fapc::head3d
