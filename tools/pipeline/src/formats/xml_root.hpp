// Which XML language a document is in, from its root element and that element's namespace
// (docs/bml.md, "Inputs named .xml"): the first start tag after the prolog (declaration, comments,
// processing instructions, doctype), read without parsing the rest.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "fapc/codec/diagnostic.hpp"

namespace fapc::pipeline {

struct XmlRoot {
  std::string name;  // the local name ("bml", "fml-apml")
  std::string ns;    // the default namespace or the prefix's, as declared on the root ("" when none)
  Location where;    // the root's '<'
};

// An error (at its byte) when the text has no start tag after a well-formed prolog.
Result<XmlRoot> find_xml_root(std::string_view text, const std::string& file_name);

// `name` in lower case (ASCII), as rows name their roots: <BML> is <bml>.
std::string lower_case(std::string name);

}  // namespace fapc::pipeline
