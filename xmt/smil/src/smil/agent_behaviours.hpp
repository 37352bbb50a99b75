// SMIL-Agent affects and actions as BML behaviours (docs/smil.md, "Affects" and "Actions"): what
// the BML reader's lowering draws (bml/bml_model.hpp), so that an affect and a faceLexeme reach
// the FAPs by one path.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "bml/bml_model.hpp"

namespace fapc::smil {

// One row of smil_affects.tsv.
struct AffectRow {
  std::string affect;
  std::string behaviour;  // a faceLexeme, or AU<n>
  double amount = 1;
  std::string reason;
};

// The bundled table, read once. It is fapc's own file, checked by tests/smil/smil_affects_test.cpp
// (every row well formed, every lexeme and unit known), so a malformed row is a build defect and
// is skipped rather than reported to users.
const std::vector<AffectRow>& affect_rows();

// The behaviours of an affect (names compare without case) at `intensity`; empty when unknown.
std::vector<bml::Behaviour> affect_behaviours(const std::string& affect, double intensity, bool shift,
                                              const Location& where);

// The channel an action acts on, by the name's ending (Xface's alice-eyes, alice-head).
enum class Channel { eyes, head, other };
Channel channel_of(const std::string& channel);

struct Action {
  std::string type;                 // action-type: turning, pointing, blink
  std::vector<std::string> params;  // the parameter elements' text
  Channel channel = Channel::eyes;
  double intensity = 1;
  bool shift = false;  // fill="freeze"
  Location where;
};

// The behaviours of an action, or nothing (with `why` set) when fapc does not know it.
std::vector<bml::Behaviour> action_behaviours(const Action& action, std::string& why);

}  // namespace fapc::smil
