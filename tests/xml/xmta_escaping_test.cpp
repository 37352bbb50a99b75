// The XMT-A writer escapes attribute values itself (the MPEG-4 layer links no XML library): a
// StreamSource url with every character that needs it must come out escaped, and the document
// must still be well-formed and valid to Xerces-C.
#include <gtest/gtest.h>

#include <string>

#include "fapc/mpeg4/xmta_writer.hpp"
#include "fapc/xml/xml_validation.hpp"

namespace fapc::mpeg4 {
namespace {

TEST(XmtaEscaping, AttributeValuesSurviveEveryCharacterThatNeedsEscaping) {
  const std::string text = write_xmta_fba_scene(fba_decoder_specific_info(), "a&b\"c<d>e\tf\r\ng.mp4#10");
  EXPECT_NE(text.find("url=\"a&amp;b&quot;c&lt;d&gt;e&#9;f&#13;&#10;g.mp4#10\""), std::string::npos) << text;
  const auto report = xml::validate_xml(text, "escaped.xmt");
  ASSERT_TRUE(report.ok()) << format_diagnostic(report.error());
  EXPECT_TRUE(report->valid()) << (report->problems.empty() ? "" : format_diagnostic(report->problems[0]));
}

}  // namespace
}  // namespace fapc::mpeg4
