// docs/schemas/xmt-o.xsd through fapc's validator (Xerces-C): the corpus documents are valid, and
// the schema rejects what the reader rejects or skips. Every verdict here was also checked with
// a second validator, libxml2's (`xmllint --noout --schema docs/schemas/xmt-o.xsd FILE`); the
// messages and positions are Xerces-C's, as fapc prints them.
#include <gtest/gtest.h>

#include <filesystem>

#include "fapc/xml/xml_validation.hpp"
#include "support/test_support.hpp"

namespace fapc::xmt {
namespace {

std::string in_body(const std::string& content) {
  return "<XMT-O xmlns=\"urn:mpeg:mpeg4:xmto:schema:2002\">\n<body>\n" + content + "\n</body>\n</XMT-O>\n";
}

// The first problem, formatted; "valid" when there is none.
std::string first_problem(const std::string& text) {
  const auto report = validate_xml(text, "s.xmt");
  if (!report.ok()) return "not validated: " + format_diagnostic(report.error());
  EXPECT_EQ(report->kind, "XMT-Omega");
  if (report->problems.empty()) return "valid";
  return format_diagnostic(report->problems.front());
}

TEST(XmtoSchema, CorpusDocumentsAreValidExceptTheOneShowingWhatIsSkipped) {
  for (const std::string& path : test::files_under(test::corpus_dir() + "/xmto", ".xmt")) {
    const bool skips_things = std::filesystem::path(path).filename() == "unsupported.xmt";
    const auto report = validate_xml(test::read_text(path), path);
    ASSERT_TRUE(report.ok()) << format_diagnostic(report.error());
    EXPECT_EQ(report->valid(), !skips_things) << path;
  }
}

TEST(XmtoSchema, ForeignElementsAndAttributesAreAllowed) {
  // FML moves (read by the FML rules) and other vocabularies (reported and skipped): the schema lets them be.
  EXPECT_EQ(first_problem("<XMT-O xmlns=\"urn:mpeg:mpeg4:xmto:schema:2002\" xmlns:f=\"urn:example:fml\">\n"
                          "<body><par><f:expr type=\"smile\"/><set attributeName=\"3\" to=\"1\" dur=\"1s\" "
                          "f:note=\"x\"/></par></body>\n</XMT-O>\n"),
            "valid");
}

TEST(XmtoSchema, RejectsWhatTheReaderRejects) {
  EXPECT_EQ(first_problem(in_body(R"(<animate attributeName="open_jaw" from="0" to="1" dur="3x"/>)")),
            "s.xmt:3:56: error: value '3x' does not match any member types of the union");
  EXPECT_EQ(first_problem(in_body(R"(<animate attributeName="open_jaw" from="0" to="1" dur="1s" calcMode="spline"/>)")),
            "s.xmt:3:70: error: value 'spline' not in enumeration");
  EXPECT_EQ(first_problem(in_body(R"(<animate attributeName="open_jaw" from="0" to="1" dur="1s" repeatCount="0"/>)")),
            "s.xmt:3:73: error: value '0' does not match any member types of the union");
  EXPECT_EQ(first_problem(in_body(R"(<set attributeName="open_jaw" dur="1s"/>)")),
            "s.xmt:3:41: error: missing required attribute 'to'");
  EXPECT_EQ(first_problem(in_body(R"(<set to="1" dur="1s"/>)")),
            "s.xmt:3:23: error: missing required attribute 'attributeName'");
  EXPECT_EQ(first_problem(in_body(R"(<par fill="sometimes"/>)")),
            "s.xmt:3:12: error: value 'sometimes' not in enumeration");
  EXPECT_EQ(first_problem("<XMT-O xmlns=\"urn:mpeg:mpeg4:xmto:schema:2002\">\n<head/>\n</XMT-O>\n"),
            "s.xmt:3:9: error: missing elements in content model '(head?,body)'");
}

TEST(XmtoSchema, RejectsWhatTheReaderOnlySkips) {
  EXPECT_EQ(first_problem(in_body(R"(<video src="a.mp4"/>)")),
            "s.xmt:3:21: error: no declaration found for element 'video'");
}

TEST(XmtoSchema, DocumentsWithoutTheNamespaceAreNotValidated) {
  const auto report = validate_xml("<XMT-O><body/></XMT-O>", "s.xmt");
  ASSERT_FALSE(report.ok());
  EXPECT_EQ(
      format_diagnostic(report.error()),
      "s.xmt:1:1: error: no schema for root element 'XMT-O'; fapc validates XMT-A "
      "(urn:mpeg:mpeg4:xmta:schema:2002), XMT-Omega (urn:mpeg:mpeg4:xmto:schema:2002), FML, "
      "BML 1.0 (http://www.bml-initiative.org/bml/bml-1.0), BML (Greta) (http://www.mindmakers.org/projects/BML), BML, "
      "FML-APML, APML, SMIL-Agent");
}

}  // namespace
}  // namespace fapc::xmt
