// Every document of corpus/xmto-bad/ is rejected with exactly this diagnostic (file:line:col, the
// message, the source line and the caret). The texts were written from the reader's rules and
// checked against the first run: positions point at the offending attribute (or the element's
// '<' when no attribute is to blame), XML errors carry libxml2's own position.
#include <gtest/gtest.h>

#include <map>

#include "fapc/xmto/xmto.hpp"
#include "support/test_support.hpp"

namespace fapc::xmto {
namespace {

const std::map<std::string, std::string>& expected_errors() {
  static const std::map<std::string, std::string> table = {
      {"animation-url.xmt",
       "animation-url.xmt:4:16: error: src 'https://example.org/smile.fap': only local files can be "
       "placed, not URLs\n"
       "    <animation src=\"https://example.org/smile.fap\"/>\n"
       "               ^"},
      {"animation-without-src.xmt",
       "animation-without-src.xmt:4:5: error: animation needs src (or ref) naming the input to place\n"
       "    <animation begin=\"1s\"/>\n"
       "    ^"},
      {"bad-clock.xmt",
       "bad-clock.xmt:4:57: error: dur '3x': expected a clock value such as 3, 3s, 250ms or "
       "00:00:03.5, indefinite or media\n"
       "    <animate attributeName=\"open_jaw\" from=\"0\" to=\"100\" dur=\"3x\"/>\n"
       "                                                        ^"},
      {"bad-fill.xmt",
       "bad-fill.xmt:4:10: error: fill 'sometimes': expected freeze, remove, hold, transition, auto or default\n"
       "    <par fill=\"sometimes\"/>\n"
       "         ^"},
      {"bad-repeat-count.xmt",
       "bad-repeat-count.xmt:4:64: error: repeatCount '-1': expected a number greater than 0 or indefinite\n"
       "    <animate attributeName=\"open_jaw\" from=\"0\" to=\"1\" dur=\"1s\" repeatCount=\"-1\"/>\n"
       "                                                               ^"},
      {"bad-values.xmt",
       "bad-values.xmt:4:39: error: values '1;x;3': expected numbers separated by ';'\n"
       "    <animate attributeName=\"open_jaw\" values=\"1;x;3\" dur=\"1s\"/>\n"
       "                                      ^"},
      {"empty.xmt", "empty.xmt:1:1: error: not well-formed XML: Document is empty"},
      {"event-begin.xmt",
       "event-begin.xmt:6:68: error: begin 'intro.end+1s': sync-base and event timing are not supported\n"
       "      <animate attributeName=\"head_yaw\" from=\"0\" to=\"100\" dur=\"1s\" begin=\"intro.end+1s\"/>\n"
       "                                                                   ^"},
      {"fap-1-as-value.xmt",
       "fap-1-as-value.xmt:4:10: error: FAP 1 (viseme) is not one value: animate viseme.<name> or "
       "expression.<name> weights instead\n"
       "    <set attributeName=\"1\" to=\"3\" dur=\"1s\"/>\n"
       "         ^"},
      {"fml-container.xmt",
       "fml-container.xmt:6:7: error: FML 'seq' inside XMT-Omega: only FML moves (talk, expr, hdmv, fap, param, "
       "wait) are read here; use XMT-Omega's own time containers, or place an FML document with animation src\n"
       "      <fml:seq>\n"
       "      ^"},
      {"from-only.xmt",
       "from-only.xmt:4:39: error: animate needs values, to or by (from alone animates nothing)\n"
       "    <animate attributeName=\"open_jaw\" from=\"0\" dur=\"1s\"/>\n"
       "                                      ^"},
      {"includes-itself.xmt",
       "includes-itself.xmt:4:16: error: animation includes a document that is being read: "
       "includes-itself.xmt -> includes-itself.xmt\n"
       "    <animation src=\"includes-itself.xmt\" begin=\"1s\"/>\n"
       "               ^"},
      {"indefinite-at-top.xmt",
       "indefinite-at-top.xmt:4:5: error: animate has no duration and nothing around it ends: give it "
       "a duration, or place it in a parallel with a known end (repeatCount=\"indefinite\" needs an "
       "end: from a par with dur, end, repeatDur or --duration)\n"
       "    <animate attributeName=\"open_jaw\" from=\"0\" to=\"100\" dur=\"1s\" repeatCount=\"indefinite\"/>\n"
       "    ^"},
      {"keytimes-count.xmt",
       "keytimes-count.xmt:4:57: error: keyTimes has 2 times for 3 values\n"
       "    <animate attributeName=\"open_jaw\" values=\"0;100;50\" keyTimes=\"0;1\" dur=\"1s\"/>\n"
       "                                                        ^"},
      {"keytimes-end.xmt",
       "keytimes-end.xmt:4:54: error: keyTimes must end with 1 unless calcMode is discrete\n"
       "    <animate attributeName=\"open_jaw\" values=\"0;100\" keyTimes=\"0;0.5\" dur=\"1s\"/>\n"
       "                                                     ^"},
      {"no-attribute-name.xmt",
       "no-attribute-name.xmt:4:5: error: animate needs attributeName (a FAP name or number)\n"
       "    <animate from=\"0\" to=\"100\" dur=\"1s\"/>\n"
       "    ^"},
      {"no-body.xmt",
       "no-body.xmt:2:1: error: XMT-O has no body\n"
       "<XMT-O>\n"
       "^"},
      {"not-well-formed.xmt",
       "not-well-formed.xmt:5:10: error: not well-formed XML: Opening and ending tag mismatch: seq "
       "line 4 and body\n"
       "  </body>\n"
       "         ^"},
      {"set-without-to.xmt",
       "set-without-to.xmt:4:5: error: set needs a to value\n"
       "    <set attributeName=\"open_jaw\" dur=\"1s\"/>\n"
       "    ^"},
      {"spline-calcmode.xmt",
       "spline-calcmode.xmt:4:66: error: calcMode 'spline' is not supported: expected linear, discrete or paced\n"
       "    <animate attributeName=\"open_jaw\" from=\"0\" to=\"100\" dur=\"1s\" calcMode=\"spline\"\n"
       "                                                                 ^"},
      {"starts-before-zero.xmt",
       "starts-before-zero.xmt:5:7: error: set starts before time 0 (at -0.5 s)\n"
       "      <set attributeName=\"open_jaw\" to=\"10\" dur=\"1s\" begin=\"-0.5s\"/>\n"
       "      ^"},
      {"two-bodies.xmt",
       "two-bodies.xmt:4:3: error: a second body: an XMT-O document has one\n"
       "  <body/>\n"
       "  ^"},
      {"undeclared-prefix.xmt",
       "undeclared-prefix.xmt:4:36: error: XML namespace error: Namespace prefix fml on expr is not defined\n"
       "    <fml:expr type=\"smile\" val=\"80\"/>\n"
       "                                   ^"},
      {"unknown-fap.xmt",
       "unknown-fap.xmt:4:14: error: unknown FAP name 'opn_jaw'; did you mean open_jaw, shift_jaw or "
       "head_yaw? (attributeName takes a FAP name or number 3..68, viseme.<name> or expression.<name>)\n"
       "    <animate attributeName=\"opn_jaw\" from=\"0\" to=\"100\" dur=\"1s\"/>\n"
       "             ^"},
      {"unknown-viseme.xmt",
       "unknown-viseme.xmt:4:10: error: unknown viseme 'zz'; the names are none PP FF TH DD kk CH SS "
       "nn RR AA E ih oh ou\n"
       "    <set attributeName=\"viseme.zz\" to=\"63\" dur=\"1s\"/>\n"
       "         ^"},
      {"wrong-root.xmt",
       "wrong-root.xmt:2:1: error: not an XMT-Omega document: the root element is 'smil', expected XMT-O\n"
       "<smil>\n"
       "^"},
      {"xmt-a-input.xmt",
       "xmt-a-input.xmt:2:1: error: XMT-A input is not supported: fapc writes XMT-A (.xmt output) but "
       "reads XMT-Omega, whose root is XMT-O\n"
       "<XMT-A xmlns=\"urn:mpeg:mpeg4:xmta:schema:2002\">\n"
       "^"},
      {"zero-dur.xmt",
       "zero-dur.xmt:4:57: error: dur must be greater than 0, found '0s'\n"
       "    <animate attributeName=\"open_jaw\" from=\"0\" to=\"100\" dur=\"0s\"/>\n"
       "                                                        ^"},
  };
  return table;
}

// Includes are refused or loaded as an empty timeline: the reader's own checks are under test.
XmtoOptions options() {
  XmtoOptions options;
  options.load_animation = [](const std::string&, const Location&) -> Result<IncludedAnimation> {
    return IncludedAnimation{};
  };
  return options;
}

TEST(XmtoRejects, EveryBadDocumentGivesItsExactDiagnostic) {
  const std::string folder = test::corpus_dir() + "/xmto-bad/";
  const std::vector<std::string> files = test::files_under(folder, ".xmt");
  EXPECT_EQ(files.size(), expected_errors().size()) << "every bad document needs its expected error";
  for (const std::string& path : files) {
    const std::string name = path.substr(folder.size());
    // Read under its bare name, so that messages do not depend on where the sources are.
    const auto read = read_xmto(test::read_text(path), name, options());
    ASSERT_FALSE(read.ok()) << name << " was accepted";
    const auto expected = expected_errors().find(name);
    ASSERT_NE(expected, expected_errors().end()) << name << ": " << render_with_caret(read.error());
    EXPECT_EQ(render_with_caret(read.error()), expected->second) << name;
  }
}

}  // namespace
}  // namespace fapc::xmto
