// The default offsets of each behaviour's sync points from its start (docs/bml.md, "Defaults"):
// where a point falls when no constraint names it, and how long a behaviour lasts by itself.
#pragma once

#include <string_view>

#include "bml/bml_model.hpp"

namespace fapc::bml {

// `behaviour` is read (kind, shift, repetition); speech has its own (its audio).
std::array<double, kStandardPoints> default_offsets(const Behaviour& behaviour);

}  // namespace fapc::bml
