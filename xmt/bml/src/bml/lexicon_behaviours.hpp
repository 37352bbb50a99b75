// A behaviour lexicon row (fapc::vocabulary, docs/intentions.md) as the BML behaviour it stands
// for, placed at the row's fractions of a span: the one way lexicon rows become behaviours, for
// FML-APML and APML intentions (fapc::intent) and Greta's references (docs/bml.md).
#pragma once

#include <array>

#include "bml/bml_model.hpp"

namespace fapc::bml {

// The behaviour of `row` at `strength` (its amount, or for gaze and head turns its angle, scaled).
Behaviour behaviour_of(const vocabulary::LexiconRow& row, double strength, const Location& where);

// BML's seven sync points from the row's fractions of [start, end]: the peak (ready) is also the
// stroke, a nod's first extreme; the swings end by relax. `onset_scale` stretches (above 1) or
// shortens the rise to the peak and the fall from relax, each kept within the span.
std::array<double, kStandardPoints> points_of(const vocabulary::LexiconRow& row, double start, double end,
                                              double onset_scale = 1);

}  // namespace fapc::bml
