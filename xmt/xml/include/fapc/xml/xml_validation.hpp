// Schema validation of the XML documents the project reads and writes, with Xerces-C. The schema
// is chosen by the document's root element (schema_registry.cpp maps roots to the schemas of
// docs/schemas/, which are compiled in). No network, no external entities, no schema named by
// the document itself: only the project's own schemas are used.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "fapc/codec/diagnostic.hpp"

namespace fapc::xml {

struct ValidationReport {
  std::string kind;      // "XMT-A", ...
  std::string schema;    // "xmt-a.xsd"
  Diagnostics problems;  // errors and warnings with line and column; no errors: valid
  bool valid() const;
};

// An error (not a report) when the document has no root element the project has a schema for,
// or is not well-formed before its root element.
Result<ValidationReport> validate_xml(std::string_view text, const std::string& file);

// "XMT-A (urn:mpeg:mpeg4:xmta:schema:2002)", ...: what validate_xml knows, for messages.
std::vector<std::string> validated_document_kinds();

}  // namespace fapc::xml
