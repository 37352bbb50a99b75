// fapc's XML validation: XMT-A against docs/schemas/xmt-a.xsd, with positions that point at the
// offending attribute; documents it has no schema for; nothing outside the document is read.
#include <gtest/gtest.h>

#include <regex>

#include "fapc/mpeg4/scene.hpp"
#include "fapc/mpeg4/xmta_writer.hpp"
#include "fapc/xml/xml_validation.hpp"
#include "support/test_support.hpp"

namespace fapc::xmt {
namespace {

// A small valid document, edited by each test. Line 10 holds the FAP node.
const std::string kDocument = R"(<?xml version="1.0" encoding="UTF-8"?>
<XMT-A xmlns="urn:mpeg:mpeg4:xmta:schema:2002">
<Header><InitialObjectDescriptor objectDescriptorID="od1" binaryID="1">
<Profiles ODProfileLevelIndication="255" sceneProfileLevelIndication="254" audioProfileLevelIndication="255" visualProfileLevelIndication="255" graphicsProfileLevelIndication="254"/>
<Descr><esDescr><ES_Descriptor ES_ID="scene" binaryID="1"><decConfigDescr><DecoderConfigDescriptor streamType="3" objectTypeIndication="1"/></decConfigDescr>
<slConfigDescr><SLConfigDescriptor predefined="2"/></slConfigDescr></ES_Descriptor></esDescr></Descr>
</InitialObjectDescriptor></Header>
<Body>
<par begin="0" isRAP="yes"><Replace><Scene><Group><children><Face DEF="FACE"><fap>
<FAP DEF="PARAMS" open_jaw="120"/>
</fap></Face></children></Group></Scene></Replace></par>
<par begin="0.04"><Replace atNode="PARAMS" atField="open_jaw" value="200"/></par>
</Body>
</XMT-A>
)";

std::string edited(const std::string& from, const std::string& to) {
  const std::size_t at = kDocument.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  std::string text = kDocument;
  return text.replace(at, from.size(), to);
}

// The formatted problems of a document, one per line.
std::string problems(const std::string& text) {
  auto report = validate_xml(text, "doc.xmt");
  if (!report.ok()) return "not validated: " + format_diagnostic(report.error());
  std::string out;
  for (const Diagnostic& d : report->problems) out += format_diagnostic(d) + "\n";
  return out;
}

TEST(XmlValidation, TheBaseDocumentIsValid) { EXPECT_EQ(problems(kDocument), ""); }

TEST(XmlValidation, UnknownFapFieldPointsAtTheAttribute) {
  // GPAC drops an unknown field with only a warning and exit status 0; the schema catches it.
  EXPECT_EQ(problems(edited("open_jaw=\"120\"", "jaw_open=\"120\"")),
            "doc.xmt:10:19: error: attribute 'jaw_open' is not declared for element 'FAP'\n");
}

TEST(XmlValidation, NonNumericValuePointsAtTheValue) {
  // GPAC stores "abc" as 0 without a message.
  EXPECT_EQ(problems(edited("open_jaw=\"120\"", "open_jaw=\"abc\"")),
            "doc.xmt:10:29: error: value 'abc' does not match regular expression facet '[+\\-]?[0-9]+'\n");
}

TEST(XmlValidation, FapOutsideFaceIsRejected) {
  const std::string text = edited("<Face DEF=\"FACE\"><fap>\n<FAP DEF=\"PARAMS\" open_jaw=\"120\"/>\n</fap></Face>",
                                  "<FAP DEF=\"PARAMS\" open_jaw=\"120\"/>");
  EXPECT_NE(problems(text).find("doc.xmt:9:"), std::string::npos) << problems(text);
}

TEST(XmlValidation, ReplaceOfAnUndefinedNodeIsRejectedWhereItIsNamed) {
  EXPECT_EQ(problems(edited("atNode=\"PARAMS\"", "atNode=\"PARAM\"")),
            "doc.xmt:12:36: error: ID attribute 'PARAM' is referenced but was never declared\n");
}

TEST(XmlValidation, ClockValuesAreNotSeconds) {
  // GPAC reads begin with atof: "00:00:01" would silently become 0.
  EXPECT_NE(problems(edited("begin=\"0.04\"", "begin=\"00:00:01\"")).find("doc.xmt:12:"), std::string::npos);
}

TEST(XmlValidation, VisemeSelectOutOfRange) {
  const std::string text = edited("<FAP DEF=\"PARAMS\" open_jaw=\"120\"/>",
                                  "<FAP DEF=\"PARAMS\"><viseme><Viseme viseme_select1=\"40\"/></viseme></FAP>");
  EXPECT_NE(problems(text).find("doc.xmt:10:"), std::string::npos) << problems(text);
}

TEST(XmlValidation, MalformedXmlHasALineAndColumn) {
  EXPECT_EQ(problems(edited("</Body>", "</Bdy>")), "doc.xmt:13:3: error: expected end of tag 'Body'\n");
}

TEST(XmlValidation, DocumentsWithoutASchemaAreAnError) {
  auto report = validate_xml("<?xml version=\"1.0\"?>\n<bml/>\n", "x.bml");
  ASSERT_FALSE(report.ok());
  EXPECT_EQ(format_diagnostic(report.error()),
            "x.bml:1:1: error: no schema for root element 'bml'; fapc validates XMT-A "
            "(urn:mpeg:mpeg4:xmta:schema:2002), XMT-Omega (urn:mpeg:mpeg4:xmto:schema:2002), FML");
  // XMT-A without its namespace is not XMT-A.
  EXPECT_FALSE(validate_xml("<XMT-A/>", "x.xmt").ok());
}

TEST(XmlValidation, NothingOutsideTheDocumentIsRead) {
  // An external DTD and an external entity naming a local file: neither is read (the entity
  // expands to nothing) and the document is judged on its own content.
  std::string text = kDocument;
  text.insert(text.find("<XMT-A"),
              "<!DOCTYPE XMT-A SYSTEM \"http://example.invalid/x.dtd\" "
              "[<!ENTITY secret SYSTEM \"file:///etc/hostname\">]>\n");
  text.insert(text.find("<Body>") + 6, "&secret;");
  EXPECT_EQ(problems(text), "");
}

TEST(XmlValidation, GpacShapedExampleValidates) {
  // GPAC's three-track example (corpus/xmta/gpac-three-tracks.xmt, docs/mp4-and-xmta.md
  // section 6.4), from which GPAC builds a scene, OD and FBA track: the schema accepts the shape
  // GPAC reads.
  const std::string path = fapc::test::corpus_dir() + "/xmta/gpac-three-tracks.xmt";
  auto report = validate_xml(fapc::test::read_text(path), path);
  ASSERT_TRUE(report.ok());
  EXPECT_TRUE(report->valid());
  EXPECT_TRUE(report->problems.empty());
}

TEST(XmlValidation, SchemaDeclaresEveryFapFieldUnderItsBifsName) {
  const std::string xsd = fapc::test::read_text(fapc::test::source_dir() + "/docs/schemas/xmt-a.xsd");
  const std::size_t begin = xsd.find("<xs:complexType name=\"FAP\">");
  const std::size_t end = xsd.find("<xs:simpleType name=\"Select\">", begin);  // the next type
  const std::string fap = xsd.substr(begin, end - begin);
  std::vector<std::string> declared;
  const std::regex int_attribute("<xs:attribute name=\"([a-z_]+)\" type=\"xs:int\"/>");
  for (auto it = std::sregex_iterator(fap.begin(), fap.end(), int_attribute); it != std::sregex_iterator(); ++it)
    declared.push_back((*it)[1]);
  std::vector<std::string> expected;
  for (int number = 3; number <= 68; ++number) expected.emplace_back(fap_field_name(number));
  EXPECT_EQ(declared, expected);
}

}  // namespace
}  // namespace fapc::xmt
