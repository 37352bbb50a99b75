// Time-value lists per target: the "curves JSON" of docs/cli.md. Plain values, no I/O.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "fapc/codec/fap_sequence.hpp"

namespace fapc {

struct Curves {
  int fps = 25;
  double duration = 0;  // seconds
  // target name (standard FAP name, "viseme", "expression", or a free parameter) -> (t, v) pairs,
  // times ascending.
  std::map<std::string, std::vector<std::pair<double, double>>> curves;
};

// The curves of a frame sequence: one point per frame where the FAP is masked. Used when the input
// is already frames (.fap, .fba); FAP 1/2 contribute "viseme"/"expression" as select1 numbers.
Curves curves_from_frames(const FapSequence& sequence);

}  // namespace fapc
