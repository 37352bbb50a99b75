#include "bases.hpp"

#include "fapc/vocabulary/arkit_shapes.hpp"

namespace fapc::pipeline::bridges {
namespace {

std::bitset<kFapCount> with_angles(const vocabulary::ShapeBasis& basis) {
  std::bitset<kFapCount> faps;
  for (int fap : basis.faps_moved()) faps.set(static_cast<std::size_t>(fap - 1));
  for (int fap : {23, 24, 25, 26, 48, 49, 50}) faps.set(static_cast<std::size_t>(fap - 1));
  return faps;
}

}  // namespace

const vocabulary::ShapeBasis& arkit_basis() { return vocabulary::arkit_shape_basis(); }

const std::vector<int>& openface_intensity_units() {
  static const std::vector<int> units = {1, 2, 4, 5, 6, 7, 9, 10, 12, 14, 15, 17, 20, 23, 25, 26, 45};
  return units;
}

const vocabulary::ShapeBasis& openface_basis() {
  static const vocabulary::ShapeBasis basis = [] {
    std::vector<std::string> keys;
    for (int au : openface_intensity_units()) keys.push_back(std::to_string(au));
    return vocabulary::ShapeBasis(vocabulary::action_unit_table(), std::move(keys));
  }();
  return basis;
}

std::bitset<kFapCount> carried_by_arkit_csv() { return with_angles(arkit_basis()); }
std::bitset<kFapCount> carried_by_openface_csv() { return with_angles(openface_basis()); }

}  // namespace fapc::pipeline::bridges
