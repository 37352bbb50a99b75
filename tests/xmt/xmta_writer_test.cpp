// The XMT-A writer: goldens for both modes, the timed-command semantics (changes only, values
// hold, BIFS field names), and every document it writes validates against docs/schemas/xmt-a.xsd.
#include <gtest/gtest.h>

#include "fapc/codec/fap_file.hpp"
#include "fapc/codec/file_io.hpp"
#include "fapc/mpeg4/xmta_writer.hpp"
#include "fapc/xml/xml_validation.hpp"
#include "support/test_support.hpp"

namespace fapc::xmt {
namespace {

void expect_valid(const std::string& text, const std::string& name) {
  auto report = validate_xml(text, name);
  ASSERT_TRUE(report.ok()) << format_diagnostic(report.error());
  EXPECT_EQ(report->kind, "XMT-A");
  for (const Diagnostic& d : report->problems) ADD_FAILURE() << format_diagnostic(d);
}

FapSequence read_example(const std::string& name) {
  const std::string path = fapc::test::corpus_dir() + "/examples/fap/" + name;
  auto bytes = read_file_bytes(path);
  EXPECT_TRUE(bytes.ok());
  auto read = read_fap_text(*bytes, path);
  EXPECT_TRUE(read.ok());
  return read->sequence;
}

TEST(XmtaWriter, FbaSceneGolden) {
  const std::string text = write_xmta_fba_scene(fba_decoder_specific_info(), "face.mp4#10");
  fapc::test::expect_golden("golden/xmta/face-fba.xmt", text);
  expect_valid(text, "face-fba.xmt");
}

TEST(XmtaWriter, CommandsGoldenFromAnExample) {
  const std::string text = write_xmta_commands(read_example("vreng-joy.fap"));
  fapc::test::expect_golden("golden/xmta/vreng-joy.bifs.xmt", text);
  expect_valid(text, "vreng-joy.bifs.xmt");
}

TEST(XmtaWriter, EveryExampleGivesAValidCommandsDocument) {
  for (const std::string& path : fapc::test::files_under(fapc::test::corpus_dir() + "/examples/fap", ".fap")) {
    SCOPED_TRACE(path);
    auto bytes = read_file_bytes(path);
    auto read = read_fap_text(*bytes, path);
    ASSERT_TRUE(read.ok());
    expect_valid(write_xmta_commands(read->sequence), path);
  }
}

TEST(XmtaWriter, CommandsCarryChangesOnlyUnderBifsFieldNames) {
  FapSequence seq;
  seq.fps = 25;
  FapFrame f0;
  f0.number = 0;
  f0.set(3, 10);  // open_jaw
  f0.set(6, 5);   // stretch_l_cornerlip in 14496-2, stretch_l_corner in BIFS
  FapFrame f1 = f0;
  f1.number = 1;  // nothing changes: no access unit
  FapFrame f2 = f0;
  f2.number = 2;
  f2.set(3, 20);
  f2.mask.set(0);  // FAP 1: viseme
  f2.viseme.select1 = 3;
  f2.viseme.blend = 63;
  FapFrame f5;
  f5.number = 5;
  f5.set(53, 7);  // stretch_l_cornerlip_o in 14496-2, stretch_l_cornerlip in BIFS
  seq.frames = {f0, f1, f2, f5};
  const std::string text = write_xmta_commands(seq);
  EXPECT_NE(text.find("<FAP DEF=\"PARAMS\" open_jaw=\"10\" stretch_l_corner=\"5\">"), std::string::npos) << text;
  EXPECT_EQ(text.find("begin=\"0.04\""), std::string::npos) << text;
  const std::string at_2 =
      "    <par begin=\"0.08\">\n"
      "      <Replace atNode=\"PARAMS\" atField=\"open_jaw\" value=\"20\"/>\n"
      "      <Replace atNode=\"VISEME\" atField=\"viseme_select1\" value=\"3\"/>\n"
      "      <Replace atNode=\"VISEME\" atField=\"viseme_blend\" value=\"63\"/>\n"
      "    </par>\n";
  EXPECT_NE(text.find(at_2), std::string::npos) << text;
  const std::string at_5 =
      "    <par begin=\"0.2\">\n"
      "      <Replace atNode=\"PARAMS\" atField=\"stretch_l_cornerlip\" value=\"7\"/>\n"
      "    </par>\n";
  EXPECT_NE(text.find(at_5), std::string::npos) << text;
  expect_valid(text, "changes.xmt");
}

TEST(XmtaWriter, FirstFrameAfterZeroStartsFromAnEmptyFace) {
  FapSequence seq;
  seq.fps = 30;
  FapFrame f;
  f.number = 1;
  f.set(48, -300);
  seq.frames = {f};
  const std::string text = write_xmta_commands(seq);
  EXPECT_NE(text.find("<FAP DEF=\"PARAMS\">"), std::string::npos) << text;
  EXPECT_NE(
      text.find("<par begin=\"0.033333\">\n      <Replace atNode=\"PARAMS\" atField=\"head_pitch\" value=\"-300\"/>"),
      std::string::npos)
      << text;
}

}  // namespace
}  // namespace fapc::xmt
