#include "fapc/head3d/arkit_morphs.hpp"

#include <map>
#include <string>

#include "fapc/vocabulary/arkit_shapes.hpp"
#include "fapc/vocabulary/shape_basis.hpp"

namespace fapc::head3d {

namespace {

// The FAP's morph target, or none for the FAPs that are rotations (eyeballs, head) or move no point.
const MorphTarget* fap_target(int fap) {
  for (const MorphTarget& t : morph_targets())
    if (t.fap == fap) return &t;
  return nullptr;
}

std::vector<MorphTarget> build() {
  std::vector<MorphTarget> targets;
  for (std::string_view name : vocabulary::arkit_shape_names()) {
    // Each FAP target stands for kTargetUnits of its FAP; the shape moves `amount` units of it.
    std::map<std::uint32_t, Vec3> moved;
    for (const vocabulary::MappingRow& row : vocabulary::arkit_table().rows_of(name)) {
      const MorphTarget* t = row.fap ? fap_target(row.fap) : nullptr;
      if (!t) continue;
      for (std::size_t i = 0; i < t->vertices.size(); ++i)
        moved[t->vertices[i]] = moved[t->vertices[i]] + (row.amount / kTargetUnits) * t->displacements[i];
    }
    MorphTarget shape;
    shape.name = std::string(name);
    for (const auto& [vertex, d] : moved) {
      shape.vertices.push_back(vertex);
      shape.displacements.push_back(d);
    }
    targets.push_back(std::move(shape));
  }
  return targets;
}

}  // namespace

const std::vector<MorphTarget>& arkit_targets() {
  static const std::vector<MorphTarget> targets = build();
  return targets;
}

std::vector<double> arkit_weights(const HeadFrame& frame) {
  vocabulary::FapVector faps{};
  for (std::size_t i = 0; i < faps.size(); ++i) faps[i] = frame.faps[i];
  return vocabulary::arkit_shape_basis().from_faps(faps);
}

}  // namespace fapc::head3d
