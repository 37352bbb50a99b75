// Greta's and SEMAINE's way of naming what a face, head or gaze shows (docs/bml.md, "Greta
// references"): a `reference` of Greta's lexicon inside `description type="gretabml"`, with the
// expressivity parameters beside it, read through greta_references.tsv and intentions.tsv.
#pragma once

#include "bml/bml_model.hpp"
#include "fapc/xml/once_per_name.hpp"
#include "fapc/xml/xml_document.hpp"

namespace fapc::bml {

// When `node` (a face, head or gaze) carries a gretabml reference: `b` becomes its lexicon rows
// (BehaviourKind::lexicon_rows), scaled by the expressivity; an unknown name keeps the span and
// draws nothing (warning bml.unknown_reference, at the reference, once per name). False when there
// is no reference (the element is read as BML). Errors: an intensity or parameter that is not a
// number in its range, at its element. `user`, when given (--lexicon), is looked up first: its
// face, head and gaze rows name references, its other rows the intentions of CLASS=NAME.
Result<bool> read_greta_reference(const xml::XmlDocument& doc, const xmlNode* node, Behaviour& b,
                                  xml::OncePerName& once, const vocabulary::BehaviourLexicon* user = nullptr);

}  // namespace fapc::bml
