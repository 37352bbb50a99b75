#include "intent/realize.hpp"

#include <algorithm>

#include "bml/bml_model.hpp"
#include "fapc/intent/codes.hpp"
#include "fapc/xml/text.hpp"

namespace fapc::intent {
namespace {

using vocabulary::LexiconBehaviour;
using vocabulary::LexiconRow;

// The BML behaviour a lexicon row stands for, at `strength`.
bml::Behaviour behaviour_of(const LexiconRow& row, double strength, const Location& where) {
  bml::Behaviour b;
  b.where = where;
  b.element = "intention";
  b.amount = row.amount * strength;
  switch (row.behaviour) {
    case LexiconBehaviour::lexeme:
      b.kind = bml::BehaviourKind::face_lexeme;
      b.lexeme = row.name;
      break;
    case LexiconBehaviour::unit:
      b.kind = bml::BehaviourKind::face_facs;
      b.au = row.unit;
      b.side = row.side;
      break;
    case LexiconBehaviour::head:
      b.kind = bml::BehaviourKind::head;
      b.lexeme = row.name;
      b.repetition = row.repetition;
      break;
    case LexiconBehaviour::gaze:
    case LexiconBehaviour::head_turn:
      b.kind = row.behaviour == LexiconBehaviour::gaze ? bml::BehaviourKind::gaze : bml::BehaviourKind::head_direction;
      b.influence = "EYES";
      b.offset_direction = row.name;
      b.offset_angle = row.amount * strength;
      b.amount = 1;
      break;
    case LexiconBehaviour::none:
      b.kind = bml::BehaviourKind::not_drawn;
      break;
  }
  return b;
}

// BML's seven sync points from the row's fractions of the span: the peak (ready) is also the
// stroke, a nod's first extreme; the swings end by relax.
std::array<double, bml::kStandardPoints> points_of(const LexiconRow& row, double start, double end) {
  const double length = end - start;
  auto at = [&](double fraction) { return start + fraction * length; };
  std::array<double, bml::kStandardPoints> t{};
  t[bml::kStart] = at(row.start);
  t[bml::kReady] = t[bml::kStrokeStart] = t[bml::kStroke] = at(row.ready);
  t[bml::kStrokeEnd] = t[bml::kRelax] = at(row.relax);
  t[bml::kEnd] = at(row.end);
  return t;
}

std::string named(const Intention& i) { return i.value.empty() ? i.type : i.type + " '" + i.value + "'"; }

}  // namespace

void realize(Intention& intention, const vocabulary::BehaviourLexicon& lexicon, const Coarticulation& rule,
             Timeline& out, xmt::OncePerName& once, Diagnostics& warnings) {
  const std::vector<const LexiconRow*> rows = lexicon.rows_for(intention.type, intention.value);
  if (rows.empty()) {
    const std::string what = lexicon.knows(intention.type)
                                 ? "the " + intention.type + " '" + intention.value + "' has no row in the lexicon"
                                 : "the intention <" + intention.type + "> is not in the lexicon";
    Diagnostic d = make_warning(codes::intent::unknown_intention, intention.where,
                                what + " (" + lexicon.source + "): nothing is drawn, its span is kept");
    once.report("unknown " + intention.type + " " + intention.value, std::move(d));
    return;
  }
  for (const LexiconRow* row : rows) {
    if (row->behaviour == LexiconBehaviour::none) {
      once.report("none " + intention.type + " " + intention.value,
                  make_warning(codes::intent::not_drawn, intention.where,
                               named(intention) + " is drawn as nothing (" + lexicon.source + " line " +
                                   std::to_string(row->line) + ": " + row->reason + "); its span is kept"));
      continue;
    }
    const bml::Behaviour b = behaviour_of(*row, intention.strength, intention.where);
    bml::lower_behaviour(b, points_of(*row, intention.start, intention.end), 0, rule, out, warnings);
    ++intention.behaviours;
  }
}

Result<double> read_strength(const xml::XmlDocument& doc, const xmlNode* node, const char* attribute) {
  const auto text = xml::attribute(node, attribute);
  if (!text) return 1.0;
  const auto value = xml::decimal(xml::trim(*text));
  if (!value || *value < 0 || *value > 1)
    return doc.error(codes::intent::bad_value, node, attribute,
                     std::string(attribute) + " '" + *text + "' is not a number from 0 to 1");
  return *value;
}

}  // namespace fapc::intent
