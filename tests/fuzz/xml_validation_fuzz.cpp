// libFuzzer target: `fapc validate`, i.e. Xerces-C parsing and validating against the project's
// schemas (XMT-A, XMT-Omega, FML, chosen by the root element). It must never crash, hang or
// recurse past the stack whatever the document (deep nesting, long value lists, entities), and
// every error and problem it reports must be placed in the document.
#include <cstdint>
#include <string_view>

#include "diagnostic_checks.hpp"
#include "fapc/xml/xml_validation.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  auto report = fapc::xml::validate_xml(text, "fuzz.xml");
  if (!report) {
    fapc::fuzz::require_placed(report.error());
    return 0;
  }
  for (const fapc::Diagnostic& problem : report->problems) fapc::fuzz::require_placed(problem);
  return 0;
}
