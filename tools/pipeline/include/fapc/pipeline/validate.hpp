// Validate: an XML document of the project (FML, XMT-Omega, XMT-A...) checked against the schema
// its root element selects (docs/schemas/).
#pragma once

#include <string>

#include "fapc/xml/xml_validation.hpp"

namespace fapc::pipeline {

// The file's problems (report.problems; report.valid() when none is an error), or why it could
// not be checked (unreadable, not XML, no schema for its root).
Result<xml::ValidationReport> validate(const std::string& path);

}  // namespace fapc::pipeline
