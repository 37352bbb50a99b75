// docs/schemas/fml.xsd through fapc's validator (Xerces-C): the corpus documents are valid, the
// spelling variants the reader takes are valid, and the schema rejects what the reader rejects or
// warns about. Every verdict here was also checked with a second validator, libxml2's
// (`xmllint --noout --schema docs/schemas/fml.xsd FILE` on each snippet written to a file); the
// messages and positions are Xerces-C's, as fapc prints them.
#include <gtest/gtest.h>

#include <filesystem>

#include "fapc/fml/fml.hpp"
#include "fapc/xml/xml_validation.hpp"
#include "support/test_support.hpp"

namespace fapc::xmt {
namespace {

std::string in_story(const std::string& content) { return "<fml>\n<story>\n" + content + "\n</story>\n</fml>\n"; }

// The model's items start on line 3, the story's content on line 6.
std::string with_model(const std::string& items, const std::string& content) {
  return "<fml>\n<model>\n" + items + "\n</model>\n<story>\n" + content + "\n</story>\n</fml>\n";
}

// The first problem, formatted; "valid" when there is none.
std::string first_problem(const std::string& text) {
  const auto report = validate_xml(text, "s.fml");
  if (!report.ok()) return "not validated: " + format_diagnostic(report.error());
  EXPECT_EQ(report->kind, "FML");
  EXPECT_EQ(report->schema, "fml.xsd");
  if (report->problems.empty()) return "valid";
  return format_diagnostic(report->problems.front());
}

// The reader as the command line runs it, with a fixed phoneme file and an end for indefinite
// repeats.
Result<FmlDocument> read(const std::string& text) {
  FmlOptions options;
  options.duration = 10;
  options.read_file = [](const std::string&) -> Result<std::string> {
    return std::string("h 50\n@ 80\nl 60\n@U 120\n");
  };
  return read_fml(text, "s.fml", options);
}

TEST(FmlSchema, CorpusDocumentsAreValidExceptThePublishedSampleWithItsExtensions) {
  const auto paths = test::files_under(test::corpus_dir() + "/fml", ".fml");
  ASSERT_GE(paths.size(), 5u);
  for (const std::string& path : paths) {
    const bool extended = std::filesystem::path(path).filename() == "hindawi-alg1.fml";
    const auto report = validate_xml(test::read_text(path), path);
    ASSERT_TRUE(report.ok()) << format_diagnostic(report.error());
    EXPECT_EQ(report->valid(), !extended) << path;
  }
}

// Each spelling variant of docs/fml.md, "Spellings", every repeat form, clock values, foreign
// attributes.
const std::string kVariants = with_model(
    "<character name=\"guide\"/>\n<img src=\"a.jpg\" type=\"frontal\"/>\n<param name=\"fdp\" val=\"x\"/>\n"
    "<range dir=\"1\" val=\"20\"/>\n<event id=\"quit\" val=\"-1\"/>\n<event name=\"kbd\"/>\n"
    "<template name=\"t\"><wait dur=\"1s\"/></template>",
    "<act repeat=\"quit\"><excl ev_id=\"kbd\"><seq event_value=\"F3\"><behavior template=\"t\"/></seq></excl></act>\n"
    "<par dur=\"00:01.5\" repeat=\"kbd;F3_up\"><hdmv dir=\"pitch\" value=\"-10\" end=\"1:00:00\"/>"
    "<fap type=\"open_jaw\" val=\"1e2\"/><fap type=\"fap31\" val=\".5\"/></par>\n"
    "<seq repeat=\"indefinite\" duration=\"2.5min\"><param type=\"smile\" val=\"3\"/><talk file=\"hi.pho\"/></seq>\n"
    "<wait begin=\"250ms\" end=\"1h\" repeat=\"2.5\"/>");
const std::string kForeignAttributes =
    "<fml xmlns:x=\"urn:example:x\" x:note=\"a\">\n<story xml:lang=\"en\">\n<talk "
    "x:voice=\"b\">Hi</talk>\n</story>\n</fml>\n";

TEST(FmlSchema, VariantsAndForeignAttributesAreValidAndRead) {
  for (const std::string& text : {kVariants, kForeignAttributes}) {
    EXPECT_EQ(first_problem(text), "valid") << text;
    const auto document = read(text);
    EXPECT_TRUE(document.ok()) << (document.ok() ? "" : format_diagnostic(document.error()));
  }
}

struct Rejected {
  std::string text;
  std::string problem;    // Xerces-C's first problem
  bool reader_is_silent;  // true when the reader neither fails nor warns (see the cases)
};

const std::vector<Rejected>& rejected() {
  static const std::vector<Rejected> cases = {
      {in_story(R"(<wait dur="3x"/>)"),
       R"(s.fml:3:12: error: value '3x' does not match regular expression facet '\d+:[0-5]\d:[0-5]\d(\.\d+)?|[0-5]\d:[0-5]\d(\.\d+)?|\d+(\.\d+)?(h|min|s|ms)?')",
       false},
      {in_story(R"(<wait begin="-1s"/>)"),
       R"(s.fml:3:14: error: value '-1s' does not match regular expression facet '\d+:[0-5]\d:[0-5]\d(\.\d+)?|[0-5]\d:[0-5]\d(\.\d+)?|\d+(\.\d+)?(h|min|s|ms)?')",
       false},
      {in_story(R"(<seq repeat="0"/>)"), "s.fml:3:14: error: value '0' does not match any member types of the union",
       false},
      {in_story(R"(<seq repeat="3;x"/>)"),
       "s.fml:3:14: error: value '3;x' does not match any member types of the union", false},
      {in_story(R"(<expr type="wink" val="50"/>)"), "s.fml:3:13: error: value 'wink' not in enumeration", false},
      {in_story(R"(<expr type="smile" val="150"/>)"),
       "s.fml:3:25: error: value '150' must be less than or equal to maxInclusive facet value '100'", false},
      {in_story(R"(<expr val="50"/>)"), "s.fml:3:17: error: missing required attribute 'type'", false},
      {in_story(R"(<fap type="2" val="3"/>)"),
       R"(s.fml:3:12: error: value '2' does not match regular expression facet '(fap|FAP)?0*([3-9]|[1-5]\d|6[0-8])|[a-z][a-z0-9_]*')",
       false},
      {in_story(R"(<hdmv type="yaw" val="+30"/>)"),
       R"(s.fml:3:23: error: value '+30' does not match regular expression facet '-?(\d+(\.\d*)?|\.\d+)([eE][+\-]?\d+)?')",
       false},
      // The published sample's kind of extension: the reader warns and plays the children.
      {in_story(R"(<emotion><expr type="smile"/></emotion>)"),
       "s.fml:3:10: error: no declaration found for element 'emotion'", false},
      {in_story(R"(<seq fill="freeze"/>)"), "s.fml:3:6: error: attribute 'fill' is not declared for element 'seq'",
       false},
      {in_story("hello"), "s.fml:4:1: error: no character data is allowed by content model", false},
      // The reader says "Hi" and warns that the markup inside talk is skipped.
      {in_story(R"(<talk>Hi <b>there</b></talk>)"), "s.fml:3:13: error: no declaration found for element 'b'", false},
      {"<fml>\n<model/>\n</fml>\n", "s.fml:3:7: error: missing elements in content model '(model*,story,model*)'",
       false},
      {"<fml>\n<story/>\n<story/>\n</fml>\n",
       "s.fml:4:7: error: element 'story' is not allowed for content model '(model*,story,model*)'", false},
      {with_model(R"(<range type="left"/>)", "<wait/>"), "s.fml:3:21: error: missing required attribute 'val'", false},
      {with_model(R"(<range type="sideways" val="3"/>)", "<wait/>"),
       "s.fml:3:14: error: value 'sideways' does not match any member types of the union", false},
      {with_model(R"(<light/>)", "<wait/>"), "s.fml:3:9: error: no declaration found for element 'light'", false},
      {with_model("<template name=\"hi\"><wait/></template>\n<template name=\"hi\"/>", R"(<behavior name="hi"/>)"),
       "s.fml:4:22: error: element 'fml' declares duplicate identity constraint unique values", false},
      {with_model("<event name=\"e\"/>\n<event id=\"e\"/>", "<wait/>"),
       "s.fml:4:16: error: element 'fml' declares duplicate identity constraint unique values", false},
      // The reader goes by local names and reads this as FML.
      {"<fml xmlns=\"urn:example:fml\">\n<story/>\n</fml>\n",
       "s.fml:1:30: error: no declaration found for element 'fml'", true},
  };
  return cases;
}

TEST(FmlSchema, RejectsWhatTheReaderRejectsOrWarnsAbout) {
  for (const Rejected& c : rejected()) {
    EXPECT_EQ(first_problem(c.text), c.problem) << c.text;
    const auto document = read(c.text);
    const bool reader_objects = !document.ok() || !document->warnings.empty();
    EXPECT_EQ(reader_objects, !c.reader_is_silent) << c.text;
  }
}

}  // namespace
}  // namespace fapc::xmt
