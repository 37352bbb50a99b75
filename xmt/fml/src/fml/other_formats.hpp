// FML's neighbours: XML languages of the Greta and Xface projects (two of them have an element
// called fml) that a user may hand to the FML reader by mistake. Naming the format beats a cascade
// of "unknown element" warnings (docs/fml.md, "Document").
#pragma once

#include <string>

#include "fapc/xml/xml_document.hpp"

namespace fapc::fml {

// "Greta FML-APML", "the fml part of a Greta FML-APML document", "APML", "BML", "Xface
// SMIL-Agent", "Greta ERL", "Greta score", "XMT-Omega", "XMT-A"; empty when the document may be FML.
// `root` is `doc`'s root; a streamed document is read only as far as its model or story.
std::string other_format_name(const xml::XmlDocument& doc, const xmlNode* root);

}  // namespace fapc::fml
