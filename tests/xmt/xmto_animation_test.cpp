// `animation src` (and ref): the included input placed at the element's begin, cut, repeated and
// frozen by the element's timing; paths resolved against the including document; inclusion
// cycles refused with the chain. The loader here is a stand-in for the command line's registry:
// it returns a known timeline and records what it was asked for.
#include <gtest/gtest.h>

#include "fapc/xmto/codes.hpp"
#include "xmto_test_helpers.hpp"

namespace fapc::xmto {
namespace {

using test::document;
using test::read_error;
using test::spans;
using test::Spans;

// One clip of open_jaw at 10 over [0, 1); the input ends at 1.5 s.
Timeline one_second() {
  Timeline t;
  Clip clip;
  clip.target = "open_jaw";
  clip.begin = 0;
  clip.end = 1;
  clip.curve = Curve::ramp(0, 10, 1, Interpolation::linear);
  clip.source = Location::text("inner.fap", 0, 0);
  t.clips.push_back(clip);
  t.explicit_end = 1.5;
  return t;
}

struct Recorder {
  std::vector<std::string> paths;
  std::vector<Location> places;

  XmtoOptions options() {
    XmtoOptions options;
    options.load_animation = [this](const std::string& path, const Location& where) -> Result<IncludedAnimation> {
      paths.push_back(path);
      places.push_back(where);
      return IncludedAnimation{one_second(), {make_warning(Location::text(path, 1, 1), "inner warning")}};
    };
    return options;
  }
};

Result<XmtoDocument> read(const std::string& body, Recorder& recorder, const std::string& file = "dir/t.xmt") {
  return read_xmto(document(body), file, recorder.options());
}

TEST(XmtoAnimation, PlacedAtTheElementsBeginWithAPathRelativeToTheDocument) {
  Recorder recorder;
  const auto doc = read(R"(<animation src="sub/a.fap" begin="2s"/>)", recorder);
  ASSERT_TRUE(doc.ok()) << format_diagnostic(doc.error());
  EXPECT_EQ(recorder.paths, std::vector<std::string>{"dir/sub/a.fap"});
  EXPECT_EQ(format_diagnostic(make_error(codes::xmto::bad_time, recorder.places.at(0), "here")),
            "dir/t.xmt:3:12: error: here");
  EXPECT_EQ(spans(doc->timeline), (Spans{{"open_jaw", 2, 3}}));
  EXPECT_EQ(doc->timeline.explicit_end, 3.5);  // the included input's own end, shifted
  EXPECT_EQ(doc->included, std::vector<std::string>{"dir/sub/a.fap"});
  EXPECT_EQ(test::messages(doc->warnings), std::vector<std::string>{"dir/sub/a.fap:1:1: warning: inner warning"});
  EXPECT_DOUBLE_EQ(test::value_at(doc->timeline, "open_jaw", 2.5), 5);
}

TEST(XmtoAnimation, RefAndFileUrlsAndAbsolutePaths) {
  Recorder recorder;
  XmtoOptions options = recorder.options();
  options.includes.allowed_folders = {"dir", "/abs"};  // an absolute path needs its folder allowed
  const auto doc =
      read_xmto(document(R"(<animation ref="b.fap"/><animation src="file:c.fap"/><animation src="/abs/d.fap"/>)"
                         R"(<animation src="e.fap" ref="ignored.fap"/>)"),
                "dir/t.xmt", options);
  ASSERT_TRUE(doc.ok()) << format_diagnostic(doc.error());
  EXPECT_EQ(recorder.paths, (std::vector<std::string>{"dir/b.fap", "dir/c.fap", "/abs/d.fap", "dir/e.fap"}));
  // The element's own warning comes before the warnings of what it included.
  const std::vector<std::string> warnings = test::messages(doc->warnings);
  ASSERT_EQ(warnings.size(), 5u);
  EXPECT_EQ(warnings[3], "dir/t.xmt:3:106: warning: ref is ignored: src is given");
}

// docs/security.md: by default a document includes from its own folder tree only.
TEST(XmtoAnimation, AbsolutePathsAndEscapesOutsideTheFolderAreRefused) {
  for (const std::string src : {"/etc/passwd", "../x.fap", "sub/../../x.fap"}) {
    Recorder recorder;
    const auto doc = read("<animation src=\"" + src + "\"/>", recorder);
    ASSERT_FALSE(doc.ok()) << src;
    EXPECT_EQ(doc.error().kind, ErrorKind::bad_input);
    EXPECT_NE(doc.error().message.find("outside the folders a script may include from ('dir')"), std::string::npos)
        << doc.error().message;
    EXPECT_EQ(doc.error().where.line, 3) << src;
    EXPECT_TRUE(recorder.paths.empty()) << "nothing is loaded";
  }
  Recorder inside;
  EXPECT_TRUE(read(R"(<animation src="sub/../x.fap"/>)", inside).ok());
  EXPECT_EQ(inside.paths, std::vector<std::string>{"dir/x.fap"});
}

TEST(XmtoAnimation, DurCutsTheIncludedInput) {
  Recorder recorder;
  const auto doc = read(R"(<animation src="a.fap" dur="0.5s"/>)", recorder);
  ASSERT_TRUE(doc.ok());
  EXPECT_EQ(spans(doc->timeline), (Spans{{"open_jaw", 0, 0.5}}));
}

TEST(XmtoAnimation, RepeatsEveryIntrinsicDuration) {
  // The input lasts 1.5 s (its explicit end), so the second run starts at 1.5.
  Recorder recorder;
  const auto doc = read(R"(<animation src="a.fap" repeatCount="2"/>)", recorder);
  ASSERT_TRUE(doc.ok());
  EXPECT_EQ(spans(doc->timeline), (Spans{{"open_jaw", 0, 1}, {"open_jaw", 1.5, 2.5}}));
  EXPECT_EQ(doc->timeline.explicit_end, 3);
}

TEST(XmtoAnimation, FillFreezeFreezesTheIncludedClips) {
  Recorder recorder;
  const auto doc =
      read(R"(<animation src="a.fap" fill="freeze"/><set attributeName="head_yaw" to="1" dur="1s"/>)", recorder);
  ASSERT_TRUE(doc.ok());
  EXPECT_EQ(doc->timeline.clips.at(0).fill, Fill::freeze);
  EXPECT_DOUBLE_EQ(test::value_at(doc->timeline, "open_jaw", 2), 10);
}

TEST(XmtoAnimation, ToAnimationStartsFromTheIncludedValue) {
  // At 0.5 s the included ramp is at 5; the to-animation goes from 5 to 0 over 0.5 s.
  Recorder recorder;
  const auto doc =
      read(R"(<par><animation src="a.fap"/><animate attributeName="open_jaw" to="0" begin="0.5s" dur="0.5s"/></par>)",
           recorder);
  ASSERT_TRUE(doc.ok());
  EXPECT_DOUBLE_EQ(test::value_at(doc->timeline, "open_jaw", 0.75), 2.5);
}

TEST(XmtoAnimation, TheLoadersErrorIsReturnedAsItIs) {
  XmtoOptions options;
  options.load_animation = [](const std::string& path, const Location&) -> Result<IncludedAnimation> {
    return make_error(codes::fap::value_count, Location::text(path, 4, 2), "bad frame");
  };
  EXPECT_EQ(read_error(document(R"(<animation src="a.fap"/>)"), options), "a.fap:4:2: error: bad frame");
}

TEST(XmtoAnimation, ADocumentThatIncludesItselfIsRefused) {
  Recorder recorder;
  EXPECT_EQ(read_error(document(R"(<animation src="./t.xmt"/>)"), recorder.options()),
            "t.xmt:3:12: error: animation includes a document that is being read: t.xmt -> t.xmt");
  XmtoOptions options = recorder.options();
  options.including = {"dir/a.xmt", "dir/b.xmt"};
  const auto cycle = read_xmto(document(R"(<animation src="../dir/a.xmt"/>)"), "dir/c.xmt", options);
  ASSERT_FALSE(cycle.ok());
  EXPECT_EQ(format_diagnostic(cycle.error()),
            "dir/c.xmt:3:12: error: animation includes a document that is being read: dir/a.xmt -> "
            "dir/b.xmt -> dir/c.xmt -> dir/a.xmt");
  EXPECT_TRUE(recorder.paths.empty());  // refused before loading anything
}

TEST(XmtoAnimation, NestingIsLimited) {
  Recorder recorder;
  XmtoOptions options = recorder.options();
  for (int i = 0; i < 16; ++i) options.including.push_back("d" + std::to_string(i) + ".xmt");
  const std::string error = read_error(document(R"(<animation src="x.xmt"/>)"), options);
  EXPECT_EQ(error.substr(0, 67), "t.xmt:3:12: error: animations nested more than 16 documents deep: d");
}

TEST(XmtoAnimation, WithoutALoaderOrWithAUrlItIsAnError) {
  EXPECT_EQ(read_error(document(R"(<animation src="a.fap"/>)")),
            "t.xmt:3:1: error: animation elements need a loader for other inputs (none was given)");
  Recorder recorder;
  EXPECT_EQ(read_error(document(R"(<animation src="http://example.com/a.fap"/>)"), recorder.options()),
            "t.xmt:3:12: error: src 'http://example.com/a.fap': only local files can be placed, not URLs");
  EXPECT_EQ(read_error(document(R"(<animation begin="1s"/>)"), recorder.options()),
            "t.xmt:3:1: error: animation needs src (or ref) naming the input to place");
}

}  // namespace
}  // namespace fapc::xmto
