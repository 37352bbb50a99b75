// An intention placed on its span to the behaviours of its lexicon rows, lowered by the BML
// reader's lowering (bml::lower_behaviour): the one path from a behaviour to FAPs.
#pragma once

#include "fapc/intent/intent.hpp"
#include "fapc/xml/once_per_name.hpp"

namespace fapc::intent {

// Draws `intention` (its start and end set) into `out`; sets its `behaviours`. Unknown intentions
// and values, and rows that draw nothing on purpose, are reported once per name through `once`.
void realize(Intention& intention, const vocabulary::BehaviourLexicon& lexicon, const Coarticulation& rule,
             Timeline& out, xml::OncePerName& once, Diagnostics& warnings);

// A strength attribute (importance, intensity, activation): 1 when absent; an error at the
// attribute when it is not a number from 0 to 1.
Result<double> read_strength(const xml::XmlDocument& doc, const xmlNode* node, const char* attribute);

}  // namespace fapc::intent
