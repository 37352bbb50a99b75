// A bml element read inside another language's document: FML-APML (fapc::intent) carries its
// speech and behaviours as a bml part, read and lowered exactly as a BML document's block.
#pragma once

#include "fapc/bml/bml.hpp"
#include "fapc/xml/xml_document.hpp"

namespace fapc::bml {

// `block` is an element of `doc` named bml (an error at it otherwise). The result's warnings
// leave out the parser's own, which belong to the whole document.
Result<BmlDocument> read_bml_block(const xml::XmlDocument& doc, const xmlNode* block, const ReaderOptions& options);

}  // namespace fapc::bml
