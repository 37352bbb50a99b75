#include "intent/realize.hpp"

#include <algorithm>

#include "bml/bml_model.hpp"
#include "bml/lexicon_behaviours.hpp"
#include "fapc/intent/codes.hpp"
#include "fapc/xml/text.hpp"

namespace fapc::intent {
namespace {

using vocabulary::LexiconBehaviour;
using vocabulary::LexiconRow;

std::string named(const Intention& i) { return i.value.empty() ? i.type : i.type + " '" + i.value + "'"; }

}  // namespace

void realize(Intention& intention, const vocabulary::BehaviourLexicon& lexicon, const Coarticulation& rule,
             Timeline& out, xml::OncePerName& once, Diagnostics& warnings) {
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
    const bml::Behaviour b = bml::behaviour_of(*row, intention.strength, intention.where);
    bml::lower_behaviour(b, bml::points_of(*row, intention.start, intention.end), 0, rule, out, warnings);
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
