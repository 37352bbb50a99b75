// docs/schemas/fml-apml.xsd, apml.xsd and smil-agent.xsd through fapc's validator (Xerces-C),
// chosen by the root element: the repository's documents of each language are valid (but the two
// FML-APML files docs/intentions.md names), and what the readers refuse or only warn about is
// invalid, placed at the attribute or element. Every verdict was also checked with libxml2
// (`xmllint --noout --schema docs/schemas/X.xsd FILE` on each snippet written to a file).
#include <gtest/gtest.h>

#include <filesystem>

#include "fapc/xml/xml_validation.hpp"
#include "schema_verdict.hpp"
#include "support/test_support.hpp"

namespace fapc::xml {
namespace {

namespace fs = std::filesystem;

using test_schema::verdict;

TEST(IntentionSchemas, RepositoryDocumentsAreValid) {
  std::size_t checked = 0;
  for (const char* folder : {"fml-apml", "apml", "smil"})
    for (const std::string& path : test::files_under(test::corpus_dir() + "/" + folder, "")) {
      // A shoulder behaviour (not BML: the reader warns) and a gaze inside the speech (skipped by the
      // reader with a warning): docs/intentions.md, "Validation".
      const std::string name = fs::path(path).filename().string();
      const bool invalid = name == "bml.xml" || name == "test_gaze_attributes.xml";
      const auto report = validate_xml(test::read_text(path), path);
      ASSERT_TRUE(report.ok()) << format_diagnostic(report.error());
      EXPECT_EQ(report->valid(), !invalid)
          << path << (report->valid() ? "" : ": " + format_diagnostic(report->problems.front()));
      ++checked;
    }
  EXPECT_EQ(checked, 88U);
}

TEST(IntentionSchemas, FmlApml) {
  const std::string speech =
      "<bml><speech id=\"s1\" language=\"english\" voice=\"marytts\"><tm id=\"tm1\"/>Hello <tm id=\"tm2\"/>"
      "<pause id=\"p\" duration_num=\"0.2\"/></speech></bml>\n";
  EXPECT_EQ(verdict("<fml-apml>" + speech +
                        "<fml>\n<emotion id=\"e1\" type=\"joy\" start=\"s1:tm1\" end=\"s1:tm2+0.5\" "
                        "importance=\"0.8\" regulation=\"felt\"/>\n</fml></fml-apml>\n",
                    "fml-apml.xsd"),
            "valid");
  EXPECT_EQ(
      verdict("<fml-apml><fml>\n<emotion id=\"e1\" type=\"joy\" end=\"1\"/>\n</fml></fml-apml>\n", "fml-apml.xsd"),
      "2:38");  // start is required
  EXPECT_EQ(verdict("<fml-apml><fml>\n<emotion id=\"e1\" start=\"0\" importance=\"2\"/>\n</fml></fml-apml>\n",
                    "fml-apml.xsd"),
            "2:40");
  EXPECT_EQ(verdict("<fml-apml><fml>\n<emotion id=\"e1\" start=\"soon\"/>\n</fml></fml-apml>\n", "fml-apml.xsd"),
            "2:25");
  EXPECT_EQ(verdict("<fml-apml><fml>\n<wish id=\"w\" start=\"0\"/>\n</fml></fml-apml>\n", "fml-apml.xsd"), "2:25");
}

TEST(IntentionSchemas, Apml) {
  EXPECT_EQ(verdict("<apml xml:lang=\"en\"><performative type=\"greet\">Hello <emphasis x-pitchaccent=\"Hstar\" "
                    "deictic=\"you\">you</emphasis><pause sec=\"0.3\"/><boundary type=\"LL\"/></performative>\n"
                    "<rheme affect=\"joy\" intensity=\"0.5\">there</rheme></apml>\n",
                    "apml.xsd"),
            "valid");
  EXPECT_EQ(verdict("<apml>\n<rheme affect=\"joy\" intensity=\"1.5\">there</rheme></apml>\n", "apml.xsd"), "2:32");
  EXPECT_EQ(verdict("<apml>\n<pause sec=\"-1\"/></apml>\n", "apml.xsd"), "2:13");
  EXPECT_EQ(verdict("<apml>\n<shout>there</shout></apml>\n", "apml.xsd"), "2:8");
}

TEST(IntentionSchemas, SmilAgent) {
  EXPECT_EQ(
      verdict(
          "<par system-language=\"english\">\n<speech id=\"s\" channel=\"alice-speech\">Hello <mark id=\"m1\"/> "
          "world</speech>\n"
          "<speech-animation content-id=\"s\" content-begin=\"m1\" affect=\"SmileOpen\" fill=\"freeze\"/>\n"
          "<seq repeat=\"2\"><action channel=\"alice-eyes\" action-type=\"turning\" intensity=\"1\"><parameter>LookLeft"
          "</parameter></action></seq></par>\n",
          "smil-agent.xsd"),
      "valid");
  EXPECT_EQ(verdict("<seq>\n<action fill=\"forever\"/></seq>\n", "smil-agent.xsd"), "2:15");
  EXPECT_EQ(verdict("<seq>\n<action intensity=\"high\"/></seq>\n", "smil-agent.xsd"), "2:20");
  EXPECT_EQ(verdict("<seq>\n<speech>Hi <mark/></speech></seq>\n", "smil-agent.xsd"), "2:19");
  EXPECT_EQ(verdict("<seq>\n<video src=\"a.mp4\"/></seq>\n", "smil-agent.xsd"), "2:21");
}

}  // namespace
}  // namespace fapc::xml
