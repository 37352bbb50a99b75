// FML's neighbours: XML languages of the Greta and Xface projects (two of them have an element
// called fml) that a user may hand to the FML reader by mistake. Naming the format beats a cascade
// of "unknown element" warnings (docs/fml.md, "Document").
#pragma once

#include <libxml/tree.h>

#include <string>

namespace fapc::xmt {

// "Greta FML-APML", "the fml part of a Greta FML-APML document", "APML", "BML", "Xface
// SMIL-Agent", "Greta ERL", "Greta score", "XMT-Omega", "XMT-A"; empty when the document may be FML.
std::string other_format_name(const xmlNode* root);

}  // namespace fapc::xmt
