// Face behaviours to FAP clips through the vocabulary (docs/bml.md, "The vocabulary"): a
// faceLexeme through bml_lexemes.tsv to action units, an action unit (faceFacs) through
// fapc::vocabulary's au_faps.tsv to FAPs.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "bml/bml_model.hpp"

namespace fapc::bml {

// The FAPs (number -> value at amount 1) of a lexeme, or of one unit on a side ('L', 'R', 'B');
// empty when unknown. Units no FAP carries are listed in `lost`.
std::map<int, double> lexeme_faps(const std::string& lexeme, std::vector<int>& lost);
std::map<int, double> unit_faps(int au, char side, double weight, std::vector<int>& lost);

// The standard lexemes of bml_lexemes.tsv, in its order.
std::vector<std::string> standard_lexemes();

// How many clips lower_face makes of a face (a unit outside the cached table aside: 0).
std::size_t face_clip_count(const Behaviour& b);

void lower_face(const Behaviour& b, const std::array<double, kStandardPoints>& t, double origin, Timeline& out,
                Diagnostics& warnings);

// The display's envelope: 0 at the start, `peak` from ready to relax, 0 at the end (a shift rises
// by its end and holds).
std::vector<KeyPoint> envelope(const std::array<double, kStandardPoints>& t, double peak, bool shift);

}  // namespace fapc::bml
