// Every document of corpus/fml-bad/ is rejected with exactly this diagnostic (file:line:col, the
// message, the source line and the caret). Each text was read against its document by hand: the
// position is the offending attribute (or the element's '<' when no attribute is to blame), XML
// errors carry libxml2's own position, phoneme file errors point into the .pho file.
#include <gtest/gtest.h>

#include <map>

#include "fapc/codec/file_io.hpp"
#include "fapc/fml/fml.hpp"
#include "support/test_support.hpp"

namespace fapc::fml {
namespace {

const std::map<std::string, std::string>& expected_errors() {
  static const std::map<std::string, std::string> table = {
      {"bad-begin.fml",
       "bad-begin.fml:2:46: error: begin '3x' is not a time (seconds: 3, 3s, 250ms, 1.5min, 00:01.5)\n"
       "  <story><action><expr type=\"smile\" val=\"50\" begin=\"3x\"/></action></story>\n"
       "                                             ^"},
      {"bad-pho.fml",
       "bad-duration.pho:3:2: error: phoneme 'h' needs a duration in milliseconds (0 to 60000)\n"
       "h\n"
       " ^"},
      {"bad-range.fml",
       "bad-range.fml:2:17: error: range type 'sideways' is not a direction (left, right, up, down, roll-left, "
       "roll-right) or an axis (0 yaw, 1 pitch, 2 roll)\n"
       "  <model><range type=\"sideways\" val=\"30\"/></model>\n"
       "                ^"},
      {"bad-repeat.fml",
       "bad-repeat.fml:3:18: error: repeat 'often' is not a count, indefinite, or an event declared in the model\n"
       "  <story><action repeat=\"often\"><expr type=\"smile\" val=\"50\"/></action></story>\n"
       "                 ^"},
      {"bad-val.fml",
       "bad-val.fml:2:35: error: 'lots' is not a number\n"
       "  <story><action><expr type=\"joy\" val=\"lots\"/></action></story>\n"
       "                                  ^"},
      {"duplicate-template.fml",
       "duplicate-template.fml:4:15: error: template 'hi' is defined twice\n"
       "    <template name=\"hi\"><talk>Hello</talk></template>\n"
       "              ^"},
      {"end-before-begin.fml",
       "end-before-begin.fml:2:60: error: end must come after begin (both count from the same point)\n"
       "  <story><action><fap type=\"open_jaw\" val=\"100\" begin=\"2s\" end=\"1s\"/></action></story>\n"
       "                                                           ^"},
      {"excl-undeclared-event.fml",
       "excl-undeclared-event.fml:2:24: error: event 'answer' is not declared in the model (<event name=\"answer\" "
       "val=\"-1\"/>)\n"
       "  <story><action><excl ev_name=\"answer\"><talk ev_val=\"0\">Yes</talk></excl></action></story>\n"
       "                       ^"},
      {"excl-without-event.fml",
       "excl-without-event.fml:2:18: error: excl needs ev_name, the event that chooses its branch\n"
       "  <story><action><excl><talk ev_val=\"0\">Yes</talk></excl></action></story>\n"
       "                 ^"},
      {"expr-without-type.fml",
       "expr-without-type.fml:2:18: error: expr needs type\n"
       "  <story><action><expr val=\"50\"/></action></story>\n"
       "                 ^"},
      {"fap-viseme.fml",
       "fap-viseme.fml:2:23: error: FAP 1 is not animated with fap: use talk (visemes) or expr (expressions)\n"
       "  <story><action><fap type=\"1\" val=\"3\"/></action></story>\n"
       "                      ^"},
      {"hindawi-alg1-as-published.fml",
       "hindawi-alg1-as-published.fml:2:20: error: not well-formed XML: AttValue: \" or ' expected\n"
       "<model><event name=“kbd”/></model>\n"
       "                   ^"},
      {"indefinite-without-end.fml",
       "indefinite-without-end.fml:2:10: error: action repeats indefinitely and nothing around it ends: give it or a "
       "parent an end (repeat=\"indefinite\" and unset loop events need an end: a container's duration or end, or "
       "--duration)\n"
       "  <story><action repeat=\"indefinite\"><expr type=\"smile\" val=\"50\"/></action></story>\n"
       "         ^"},
      {"missing-pho.fml",
       "missing-pho.fml:2:24: error: talk file 'nowhere.pho': cannot open file: No such file or directory\n"
       "  <story><action><talk file=\"nowhere.pho\"/></action></story>\n"
       "                       ^"},
      {"negative-duration.fml",
       "negative-duration.fml:2:49: error: duration '-2s' is not a time (seconds: 3, 3s, 250ms, 1.5min, 00:01.5)\n"
       "  <story><action><fap type=\"open_jaw\" val=\"100\" duration=\"-2s\"/></action></story>\n"
       "                                                ^"},
      {"no-story.fml",
       "no-story.fml:1:1: error: fml has no story: nothing to animate\n"
       "<fml>\n"
       "^"},
      {"recursive-template.fml",
       "recursive-template.fml:4:24: error: template 'a' uses itself: a -> b -> a\n"
       "    <template name=\"b\"><behavior name=\"a\"/></template>\n"
       "                       ^"},
      {"repeats-beside-a-long-sibling.fml",
       "repeats-beside-a-long-sibling.fml:5:7: error: seq repeats to too many runs: more than the limit of "
       "4000000 runs (--max-runs N raises it)\n"
       "      <seq repeat=\"indefinite\"><wait dur=\"100\"/></seq>\n"
       "      ^"},
      {"talk-empty.fml",
       "talk-empty.fml:2:18: error: talk needs text to say or a phoneme file (file=\"x.pho\")\n"
       "  <story><action><talk begin=\"1s\"/></action></story>\n"
       "                 ^"},
      {"talk-text-and-file.fml",
       "talk-text-and-file.fml:2:24: error: talk has both text and file; give one\n"
       "  <story><action><talk file=\"hello.pho\">Hello</talk></action></story>\n"
       "                       ^"},
      {"two-stories.fml",
       "two-stories.fml:3:3: error: a second story: an FML document has one\n"
       "  <story><action><wait duration=\"1s\"/></action></story>\n"
       "  ^"},
      {"unknown-fap.fml",
       "unknown-fap.fml:2:23: error: 'open_jow' is not a FAP number (3-68) or name; did you mean open_jaw, shift_jaw, "
       "head_yaw?\n"
       "  <story><action><fap type=\"open_jow\" val=\"100\"/></action></story>\n"
       "                      ^"},
      {"unknown-template.fml",
       "unknown-template.fml:3:20: error: no template 'bye' in the model (templates: hi)\n"
       "  <story><behavior name=\"bye\"/></story>\n"
       "                   ^"},
      {"wrong-root.fml",
       "wrong-root.fml:1:1: error: not an FML document: the root element is 'animation', expected fml\n"
       "<animation>\n"
       "^"},
      {"zero-repeat.fml",
       "zero-repeat.fml:2:18: error: repeat must be a count above 0\n"
       "  <story><action repeat=\"0\"><expr type=\"smile\" val=\"50\"/></action></story>\n"
       "                 ^"},
  };
  return table;
}

TEST(FmlRejects, EveryBadDocumentGivesItsExactDiagnostic) {
  const std::string folder = test::corpus_dir() + "/fml-bad/";
  const std::vector<std::string> files = test::files_under(folder, ".fml");
  EXPECT_EQ(files.size(), expected_errors().size()) << "every bad document needs its expected error";
  EXPECT_GE(files.size(), 15u);
  ReaderOptions options;
  options.read_file = [&](const std::string& path) { return read_file_bytes(folder + path); };
  for (const std::string& path : files) {
    const std::string name = path.substr(folder.size());
    // Read under its bare name, so that messages do not depend on where the sources are.
    const auto read = read_fml(test::read_text(path), name, options);
    ASSERT_FALSE(read.ok()) << name << " was accepted";
    const auto expected = expected_errors().find(name);
    ASSERT_NE(expected, expected_errors().end()) << name << ": " << render_with_caret(read.error());
    EXPECT_EQ(render_with_caret(read.error()), expected->second) << name;
  }
}

TEST(FmlRejects, NeighbouringFormatsAreNamedNotMisread) {
  // The readers of fapc are named from the list the options carry (the pipeline makes it from its
  // table: tests/pipeline/fml_names_other_readers_test.cpp); this one stands for it.
  ReaderOptions options;
  options.other_readers = {{"fml-apml", "fml-apml", ".fml-apml"},
                           {"apml", "apml", ".apml"},
                           {"bml", "bml", ".bml"},
                           {"par", "smil", ".smil"}};
  const std::map<std::string, std::string> formats = {
      {"fml-apml-bml.xml", "this is a fml-apml document (root <fml-apml>), not FML"},
      {"apml-Neutral.xml", "this is a apml document (root <apml>), not FML"},
      {"bml-BML_example2.xml", "this is a bml document (root <bml>), not FML"},
      {"smil-simpleEnglish.smil", "this is a smil document (root <par>), not FML"},
      {"other-erl_example.xml", "this is Greta ERL (expression library), not FML"},
      {"other-score.xml", "this is a Greta score, not FML"},
  };
  const std::string folder = test::corpus_dir() + "/fml-neighbours/";
  EXPECT_EQ(test::files_under(folder, "").size(), formats.size());
  for (const auto& [name, start] : formats) {
    const auto read = read_fml(test::read_text(folder + name), name, options);
    ASSERT_FALSE(read.ok()) << name;
    EXPECT_EQ(read.error().message.substr(0, start.size()), start) << read.error().message;
    EXPECT_GT(read.error().where.line, 0) << name;
  }
}

TEST(FmlRejects, AnotherReadersDocumentSaysHowToReadIt) {
  ReaderOptions options;
  options.other_readers = {{"bml", "bml", ".bml"}};
  const auto read = read_fml("<BML id=\"b\"/>\n", "b.fml", options);
  ASSERT_FALSE(read.ok());
  EXPECT_EQ(format_diagnostic(read.error()),
            "b.fml:1:1: error: this is a bml document (root <BML>), not FML (the Arya-DiPaola Face Modeling "
            "Language, root fml with model and story): fapc reads it as .bml");
  // Without the list, no reader is named: the root is reported as not FML's.
  const auto unnamed = read_fml("<bml id=\"b\"/>\n", "b.fml");
  ASSERT_FALSE(unnamed.ok());
  EXPECT_EQ(unnamed.error().message, "not an FML document: the root element is 'bml', expected fml");
}

TEST(FmlRejects, TheInnerFmlOfFmlApmlIsRecognised) {
  const auto read =
      read_fml("<fml>\n<performative id=\"p1\" type=\"greet\" start=\"0\" end=\"1\"/>\n</fml>\n", "i.xml");
  ASSERT_FALSE(read.ok());
  EXPECT_EQ(format_diagnostic(read.error()),
            "i.xml:1:1: error: this is the fml part of a Greta FML-APML document, not FML (the Arya-DiPaola "
            "Face Modeling Language, root fml with model and story): fapc does not read it");
}

}  // namespace
}  // namespace fapc::fml
