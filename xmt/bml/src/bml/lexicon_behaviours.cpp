#include "bml/lexicon_behaviours.hpp"

#include <algorithm>

namespace fapc::bml {

using vocabulary::LexiconBehaviour;

Behaviour behaviour_of(const vocabulary::LexiconRow& row, double strength, const Location& where) {
  Behaviour b;
  b.where = where;
  b.element = "intention";
  b.amount = row.amount * strength;
  switch (row.behaviour) {
    case LexiconBehaviour::lexeme:
      b.kind = BehaviourKind::face_lexeme;
      b.lexeme = row.name;
      break;
    case LexiconBehaviour::unit:
      b.kind = BehaviourKind::face_facs;
      b.au = row.unit;
      b.side = row.side;
      break;
    case LexiconBehaviour::head:
      b.kind = BehaviourKind::head;
      b.lexeme = row.name;
      b.repetition = row.repetition;
      break;
    case LexiconBehaviour::gaze:
    case LexiconBehaviour::head_turn:
      b.kind = row.behaviour == LexiconBehaviour::gaze ? BehaviourKind::gaze : BehaviourKind::head_direction;
      b.influence = "EYES";
      b.offset_direction = row.name;
      b.offset_angle = row.amount * strength;
      b.amount = 1;
      break;
    case LexiconBehaviour::none:
      b.kind = BehaviourKind::not_drawn;
      break;
  }
  return b;
}

std::array<double, kStandardPoints> points_of(const vocabulary::LexiconRow& row, double start, double end,
                                              double onset_scale) {
  const double length = end - start;
  auto at = [&](double fraction) { return start + std::clamp(fraction, 0.0, 1.0) * length; };
  double ready = row.start + (row.ready - row.start) * onset_scale;
  double relax = row.end - (row.end - row.relax) * onset_scale;
  if (ready > relax) ready = relax = (ready + relax) / 2;  // a stretched rise and fall meet in the middle
  std::array<double, kStandardPoints> t{};
  t[kStart] = at(row.start);
  t[kReady] = t[kStrokeStart] = t[kStroke] = at(ready);
  t[kStrokeEnd] = t[kRelax] = at(relax);
  t[kEnd] = at(row.end);
  return t;
}

}  // namespace fapc::bml
