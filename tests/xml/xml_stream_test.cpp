// A streamed XmlDocument (read as the walk needs it, read children freed) must show a reader what
// a parsed one shows, and must say so when it cannot: the readers then read the text again whole.
#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

#include "fapc/fml/fml.hpp"
#include "fapc/xml/xml_document.hpp"
#include "fapc/xmto/xmto.hpp"

namespace fapc::xml {
namespace {

constexpr std::array<std::string_view, 2> kOpen{"par", "seq"};

// A document of nested par/seq with leaves, comments and a talk with text, larger than the
// stream's chunk so that the walk waits for the parser many times.
std::string big_document() {
  std::string text = "<?xml version=\"1.0\"?>\n<doc>\n<head><meta name=\"a\"/></head>\n<body>\n";
  for (int i = 0; i < 2000; ++i) {
    text += "  <seq n=\"" + std::to_string(i) + "\">\n    <!-- part " + std::to_string(i) + " -->\n";
    text += "    <par><leaf a=\"1\"   b=\"2\"/><leaf\n      b=\"3\"/></par>\n";
    text += "    <talk>hello <![CDATA[there]]> " + std::to_string(i) + "</talk>\n  </seq>\n";
  }
  return text + "</body>\n</doc>\n";
}

// Every element below `element` in document order: its name, its place and its b attribute's,
// and a talk's text.
void walk(const XmlDocument& doc, const xmlNode* element, bool release, std::vector<std::string>& out) {
  for (const xmlNode* child : doc.children(element, kOpen, release)) {
    const Location at = doc.where(child);
    const Location b = doc.where(child, "b");
    out.push_back(std::string(local_name(child)) + " " + std::to_string(at.line) + ":" + std::to_string(at.column) +
                  " b " + std::to_string(b.line) + ":" + std::to_string(b.column));
    if (local_name(child) == "talk") out.push_back(text_content(child));
    walk(doc, child, release, out);
  }
}

TEST(StreamedDocument, ShowsTheWalkWhatAParsedOneShows) {
  const std::string text = big_document();
  ASSERT_GT(text.size(), 3u * 64 * 1024);
  Result<XmlDocument> parsed = XmlDocument::parse(text, "t.xml", BlankText{false, {"talk"}});
  Result<XmlDocument> streamed = XmlDocument::stream(text, "t.xml", BlankText{false, {"talk"}});
  ASSERT_TRUE(parsed.ok() && streamed.ok());
  EXPECT_TRUE(streamed->streamed());
  EXPECT_EQ(streamed->element_count(), parsed->element_count());
  std::vector<std::string> from_parse, from_stream;
  walk(*parsed, parsed->root(), false, from_parse);
  walk(*streamed, streamed->root(), true, from_stream);
  EXPECT_EQ(from_stream, from_parse);
  ASSERT_GT(from_stream.size(), 2000u);
  // Counted by hand in the text: head, meta, body, seq, then these.
  EXPECT_EQ(from_stream[4], "par 7:5 b 7:5");
  EXPECT_EQ(from_stream[5], "leaf 7:10 b 7:24");
  EXPECT_EQ(from_stream[6], "leaf 7:31 b 8:7");
  EXPECT_EQ(from_stream[7], "talk 9:5 b 9:5");
  EXPECT_EQ(from_stream[8], "hello there 0");
  // The walk freed what it read: the body has no element left.
  for (const xmlNode* child = streamed->root()->children; child; child = child->next)
    if (local_name(child) == "body") {
      EXPECT_EQ(child->children, nullptr);
    }
  EXPECT_TRUE(streamed->finish_stream());
}

// What the readers would report in another order when streamed (text and entity references where
// they look for them), parser warnings and errors: the stream says it was not faithful.
TEST(StreamedDocument, SaysWhenTheTextMustBeReadWhole) {
  const auto faithful = [](const std::string& text) {
    Result<XmlDocument> doc = XmlDocument::stream(text, "t.xml", BlankText{false, {"talk"}});
    if (!doc) return false;
    std::vector<std::string> seen;
    walk(*doc, doc->root(), true, seen);
    return doc->finish_stream();
  };
  EXPECT_TRUE(faithful("<a><par><x/></par><!-- c --><talk>words</talk></a>"));
  EXPECT_FALSE(faithful("<a><par>stray<x/></par></a>"));
  EXPECT_FALSE(faithful("<a><par><![CDATA[stray]]></par></a>"));
  EXPECT_FALSE(faithful("<!DOCTYPE a [<!ENTITY e \"x\">]><a><par>&e;</par></a>"));
  const std::string warned = "<?xml version=\"1.1\"?><a/>";  // libxml2 warns of the version
  ASSERT_TRUE(XmlDocument::parse(warned, "t.xml").ok());
  EXPECT_EQ(XmlDocument::parse(warned, "t.xml")->warnings().size(), 1u);
  EXPECT_FALSE(faithful(warned));
  EXPECT_FALSE(faithful("<a><par><x/></par>"));  // not well-formed at the end
  EXPECT_FALSE(faithful("<a><par><x/></par></a><b/>"));
}

}  // namespace
}  // namespace fapc::xml

namespace fapc::xmt {
namespace {

std::vector<std::string> messages(const Diagnostics& diagnostics) {
  std::vector<std::string> out;
  for (const Diagnostic& d : diagnostics) out.push_back(format_diagnostic(d));
  return out;
}

// An element after the body is reported before the body's own warnings (the reader reads the
// root's children first), as when the whole tree was parsed before reading.
TEST(StreamedReaders, AnElementAfterTheBodyKeepsTheOrderOfTheWarnings) {
  const std::string text =
      "<XMT-O xmlns=\"urn:mpeg:mpeg4:xmto:schema:2002\"><body>\n"
      "<par odd=\"1\"><set attributeName=\"open_jaw\" to=\"100\" dur=\"1s\"/></par>\n"
      "</body>\n<extra/></XMT-O>\n";
  Result<XmtoDocument> read = read_xmto(text, "t.xmt");
  ASSERT_TRUE(read.ok()) << format_diagnostic(read.error());
  const std::vector<std::string> got = messages(read->warnings);
  ASSERT_EQ(got.size(), 2u);
  EXPECT_EQ(got[0], "t.xmt:4:1: warning: element 'extra' is not supported and was skipped");
  EXPECT_EQ(got[1], "t.xmt:2:6: warning: attribute 'odd' of par is not supported and was ignored");
  EXPECT_EQ(read->timeline.clips.size(), 1u);
}

// A model after the story still defines the templates the story's behaviors play.
TEST(StreamedReaders, AModelAfterTheStoryIsStillRead) {
  const std::string text =
      "<fml><story><action><behavior name=\"nod\"/></action></story>\n"
      "<model><template name=\"nod\"><hdmv type=\"pitch\" val=\"8\" duration=\"1s\"/></template></model></fml>\n";
  Result<FmlDocument> read = read_fml(text, "t.fml");
  ASSERT_TRUE(read.ok()) << format_diagnostic(read.error());
  EXPECT_EQ(read->timeline.clips.size(), 1u);
  EXPECT_EQ(read->templates, std::vector<std::string>{"nod"});
}

}  // namespace
}  // namespace fapc::xmt
