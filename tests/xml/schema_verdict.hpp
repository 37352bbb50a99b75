// What fapc's validator says of a snippet, in the few characters the schema tests compare.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "fapc/xml/xml_validation.hpp"

namespace fapc::xml::test_schema {

// "valid", or the first problem as "LINE:COLUMN"; the schema chosen must be `schema`.
inline std::string verdict(const std::string& text, const std::string& schema) {
  const auto report = validate_xml(text, "snippet.xml");
  if (!report.ok()) return "not validated: " + format_diagnostic(report.error());
  EXPECT_EQ(report->schema, schema);
  if (report->problems.empty()) return "valid";
  const Diagnostic& d = report->problems.front();
  return std::to_string(d.where.line) + ":" + std::to_string(d.where.column);
}

}  // namespace fapc::xml::test_schema
