// docs/schemas/bml-core.xsd (with bml.xsd and bml-mindmakers.xsd, which give it their namespace)
// through fapc's validator (Xerces-C): the repository's BML documents are valid, each dialect's
// forms are valid, and what the reader refuses in a value is invalid, placed at the attribute or
// element. Every verdict was also checked with libxml2 (`xmllint --noout --schema
// docs/schemas/bml.xsd FILE`, or bml-core.xsd for no namespace, on each snippet written to a file).
#include <gtest/gtest.h>

#include "fapc/xml/xml_validation.hpp"
#include "schema_verdict.hpp"
#include "support/test_support.hpp"

namespace fapc::xml {
namespace {

constexpr const char* kBml10 = "http://www.bml-initiative.org/bml/bml-1.0";

std::string block(const std::string& ns, const std::string& body, const std::string& attributes = "id=\"b\"") {
  return "<bml" + (ns.empty() ? std::string() : " xmlns=\"" + ns + "\"") + " " + attributes + ">\n" + body +
         "\n</bml>\n";
}

using test_schema::verdict;

TEST(BmlSchema, RepositoryDocumentsAreValid) {
  std::vector<std::string> paths = test::files_under(test::corpus_dir() + "/bml", ".bml");
  for (const std::string& p : test::files_under(test::corpus_dir() + "/bml", ".xml")) paths.push_back(p);
  ASSERT_GE(paths.size(), 38U);
  for (const std::string& path : paths) {
    const auto report = validate_xml(test::read_text(path), path);
    ASSERT_TRUE(report.ok()) << format_diagnostic(report.error());
    EXPECT_TRUE(report->valid()) << path << ": " << format_diagnostic(report->problems.front());
  }
}

TEST(BmlSchema, TheSchemaFollowsTheNamespace) {
  EXPECT_EQ(verdict(block(kBml10, "<head id=\"h\" lexeme=\"NOD\"/>"), "bml.xsd"), "valid");
  EXPECT_EQ(
      verdict(block("http://www.mindmakers.org/projects/BML", "<head id=\"h\" lexeme=\"NOD\"/>"), "bml-mindmakers.xsd"),
      "valid");
  EXPECT_EQ(verdict(block("", "<head id=\"h\" lexeme=\"NOD\"/>"), "bml-core.xsd"), "valid");
}

TEST(BmlSchema, EachDialectsFormsAreValid) {
  // BML 1.0: sync references, constraints, core extensions in another namespace, speech marks.
  EXPECT_EQ(verdict(block(kBml10, R"(<speech id="s"><text>Hello <sync id="m1"/> world</text></speech>
<faceLexeme id="f" lexeme="RAISE_BROWS" amount="0.5" start="s:m1" end="s:end+0.5"/>
<faceFacs id="u" au="12" side="LEFT" attackPeak="b:f:ready-0.1"/>
<gaze id="g" target="camera" influence="HEAD" offsetAngle="20" offsetDirection="LEFT"/>
<head id="h" lexeme="NOD" repetition="2"/>
<gesture id="x" lexeme="BEAT" mode="RIGHT_HAND"/>
<bmlt:noise xmlns:bmlt="http://hmi.ewi.utwente.nl/bmlt" id="n" joint="skullbase"/>
<constraint><synchronize><sync ref="h:stroke"/><sync ref="f:stroke"/></synchronize>
<after ref="h:end"><sync ref="g:start"/></after></constraint>)",
                          "id=\"b\" characterId=\"Alice\" composition=\"APPEND\""),
                    "bml.xsd"),
            "valid");
  // Greta: gretabml descriptions, tm marks in the speech, lower-case composition, own attributes.
  EXPECT_EQ(
      verdict(
          block(
              "",
              R"(<speech id="s" start="0" language="english"><tm id="t1"/>Hi <pitchaccent id="p" start="s:t1" end="s:t1" type="Hstar"/></speech>
<face id="f" start="-0.5" end="2" expressivityspc="0.3"><description level="1" type="gretabml"><reference>affect=joy</reference>
<intensity>1</intensity><SPC.value>0.4</SPC.value><TMP.value>-0.7</TMP.value><OPN.value>0</OPN.value><SPC.min>-1</SPC.min></description></face>)",
              "id=\"b\" composition=\"append\""),
          "bml-core.xsd"),
      "valid");
  // SmartBody: recorded speech, lips rows, curves.
  EXPECT_EQ(verdict(block("", R"(<speech id="sp1" start="0" end="0.2"><text><sync id="T0" time="0"/>we</text>
<description level="1" type="audio/x-wav"><file ref="take"/></description></speech>
<lips viseme="W" articulation="1.0" start="0" ready="0" relax="0.05" end="0.05"/>
<curves><curve name="open" num_keys="2" owner="sp1">0 0 0 0 0.2 1 0 0</curve></curves>)"),
                    "bml-core.xsd"),
            "valid");
}

TEST(BmlSchema, WhatTheReaderRefusesIsInvalidWhereItStands) {
  EXPECT_EQ(verdict(block(kBml10, "<head id=\"h\"/>", "id=\"b\" composition=\"blend\""), "bml.xsd"), "1:76");
  EXPECT_EQ(verdict(block(kBml10, "<faceFacs id=\"u\" au=\"120\"/>"), "bml.xsd"), "2:22");
  EXPECT_EQ(verdict(block(kBml10, "<faceFacs id=\"u\" au=\"1\" side=\"UP\"/>"), "bml.xsd"), "2:31");
  EXPECT_EQ(verdict(block(kBml10, "<head id=\"h\" repetition=\"0\"/>"), "bml.xsd"), "2:26");
  EXPECT_EQ(verdict(block(kBml10, "<head id=\"h\" start=\"a:b:c:d\"/>"), "bml.xsd"), "2:21");
  EXPECT_EQ(verdict(block(kBml10, "<head id=\"h\" start=\"soon\"/>"), "bml.xsd"), "2:21");
  EXPECT_EQ(verdict(block(kBml10, "<smile id=\"s\"/>"), "bml.xsd"), "2:16");  // not a BML element
  EXPECT_EQ(verdict(block(kBml10, "<constraint><synchronize><sync/></synchronize></constraint>"), "bml.xsd"), "2:33");
  EXPECT_EQ(verdict(block("",
                          "<face id=\"f\"><description type=\"gretabml\"><reference>affect=joy</reference>\n"
                          "<SPC.value>3</SPC.value></description></face>"),
                    "bml-core.xsd"),
            "3:25");
}

}  // namespace
}  // namespace fapc::xml
