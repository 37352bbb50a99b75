// The two shape sets the writers fit FAPs to, and the FAPs each output carries besides (head and
// eye angles), built once.
#pragma once

#include <bitset>
#include <vector>

#include "fapc/vocabulary/shape_basis.hpp"

namespace fapc::pipeline::bridges {

// ARKit's 52 shapes, in Live Link Face's order.
const vocabulary::ShapeBasis& arkit_basis();
// The 17 action units whose intensities OpenFace 2.0 writes (AUxx_r), in its order.
const vocabulary::ShapeBasis& openface_basis();
const std::vector<int>& openface_intensity_units();

// FAPs an output carries: its shapes' FAPs plus the angle columns (head 48-50, eyes 23-26).
std::bitset<kFapCount> carried_by_arkit_csv();
std::bitset<kFapCount> carried_by_openface_csv();

}  // namespace fapc::pipeline::bridges
