// FML moves written inside another XML document (docs/xmt-omega.md, "FML moves inside XMT-Omega"):
// one move read by the FML reader's own rules, for the host reader to place on its timeline.
#pragma once

#include "fapc/fml/fml.hpp"
#include "fapc/xml/xml_document.hpp"
#include "fml/fml_tree.hpp"

namespace fapc::xmt {

struct EmbeddedFmlMove {
  FmlLeaf leaf;        // what the move does (move, normal, talk or wait)
  std::string target;  // a move's target
  Timing timing;       // begin, duration (always set), repeat, as the scheduler takes them
  Diagnostics warnings;
};

// Errors at the element: what read_fml would report for the move, and FML time containers or
// model items, which are read only inside an FML document (place one with animation src).
Result<EmbeddedFmlMove> read_embedded_fml_move(const xml::XmlDocument& doc, const xmlNode* move,
                                               const FmlOptions& options);

// A talk as a timeline from time 0: its viseme clips by the coarticulation rule, and its audio.
// A spoken talk keeps its own length; a silent one (letters, .pho) is stretched to `duration`.
// `where`: the talk element.
Timeline talk_timeline(const FmlTalk& talk, const Location& where, double duration, const Coarticulation& rule);

}  // namespace fapc::xmt
