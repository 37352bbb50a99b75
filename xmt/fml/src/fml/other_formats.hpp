// FML's neighbours: XML languages of the Greta and Xface projects (two of them have an element
// called fml) that a user may hand to the FML reader by mistake. Naming the format beats a cascade
// of "unknown element" warnings (docs/fml.md, "Document").
#pragma once

#include <string>
#include <vector>

#include "fapc/transcoder/reader_options.hpp"
#include "fapc/xml/xml_document.hpp"

namespace fapc::fml {

// What the document is when it is not FML: a document another reader of fapc takes, from `others`
// (ReaderOptions::other_readers: the pipeline's table), {"a bml document (root <bml>)", "fapc
// reads it as .bml"}; one no reader takes, {"Greta ERL (expression library)", "fapc does not read
// it"}; the fml part of FML-APML. `what` is empty when the document may be FML. `root` is `doc`'s
// root; a streamed document is read only as far as its model or story.
struct OtherFormat {
  std::string what;
  std::string reading;  // how fapc reads it, if it does
};
OtherFormat other_format(const xml::XmlDocument& doc, const xmlNode* root, const std::vector<OtherReader>& others);

}  // namespace fapc::fml
