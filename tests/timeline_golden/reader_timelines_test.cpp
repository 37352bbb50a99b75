// What each reader makes of the bundled examples, compared as a timeline dump (docs/timeline.md)
// with reviewed goldens under corpus/golden/timeline/<kind>/ (FAPC_REGENERATE_GOLDEN=1 rewrites
// them; review with `git diff corpus/`). Script front ends (Mimic, FML, XMT-Omega, FML-APML, APML,
// SMIL-Agent) go through the program, `fapc compile X -o - --to timeline`, so XMT-Omega's
// `animation src` reaches every registered reader. Frame inputs (.fap, .fba, .mp4) have no timeline of their own: their
// frames are lifted with timeline_from_frames(), the form an XMT-Omega include gives them.
#include <gtest/gtest.h>

#include <filesystem>
#include <span>

#include "fapc/codec/fap_file.hpp"
#include "fapc/codec/fba.hpp"
#include "fapc/codec/file_io.hpp"
#include "fapc/mpeg4/mp4_reader.hpp"
#include "fapc/timeline/timeline_from_frames.hpp"
#include "support/test_support.hpp"

namespace fapc {
namespace {

namespace fs = std::filesystem;

// `input` is relative to the source folder, as the dumps name it.
std::string golden_for(const std::string& kind, const std::string& input) {
  return "golden/timeline/" + kind + "/" + fs::path(input).stem().string() + ".timeline";
}

void expect_program_dump(const std::string& kind, const std::string& input) {
  const test::CommandRun run = test::run_fapc("compile " + input + " -o - --to timeline");
  ASSERT_EQ(run.exit_status, 0) << input << ": " << run.err;
  test::expect_golden(golden_for(kind, input), run.out);
}

std::string read_bytes(const std::string& input) {
  auto bytes = read_file_bytes(test::source_dir() + "/" + input);
  EXPECT_TRUE(bytes.ok()) << input << ": " << (bytes ? "" : format_diagnostic(bytes.error()));
  return bytes ? *bytes : std::string();
}

void expect_frames_dump(const std::string& kind, const std::string& input, const FapSequence& frames) {
  ASSERT_FALSE(frames.frames.empty()) << input;
  test::expect_golden(golden_for(kind, input), dump(timeline_from_frames(frames, 0, Location::whole_file(input))));
}

TEST(ReaderTimelines, Mimic) {
  for (const char* input : {"corpus/examples/mimic/figure3.mimic", "corpus/examples/xmto/parts/hello.mimic"})
    expect_program_dump("mimic", input);
}

TEST(ReaderTimelines, Fml) {
  for (const char* input :
       {"corpus/examples/fml/figure8.fml", "corpus/examples/fml/tour.fml", "corpus/examples/xmto/parts/smile.fml"})
    expect_program_dump("fml", input);
}

TEST(ReaderTimelines, XmtOmega) {
  for (const char* input : {"corpus/examples/xmto/compose.xmt", "corpus/examples/xmto/fml-moves.xmt"})
    expect_program_dump("xmto", input);
}

// The intention readers (docs/intentions.md): intentions on speech marks, through the lexicon.
TEST(ReaderTimelines, FmlApml) {
  for (const char* input : {"corpus/fml-apml/SEMAINE__SEMAINE-3.1/fml-embarrassment.xml",
                            "corpus/fml-apml/SEMAINE__SEMAINE-3.1/fml-apml_nospeech.xml"})
    expect_program_dump("fml-apml", input);
}

TEST(ReaderTimelines, Apml) {
  for (const char* input : {"corpus/apml/SEMAINE__SEMAINE-3.1/intensity_joy.xml"}) expect_program_dump("apml", input);
}

// SMIL-Agent (docs/smil.md): speech with marks, affects and actions.
TEST(ReaderTimelines, SmilAgent) {
  for (const char* input :
       {"corpus/smil/bestdpf__xface-new/Faps/withMarks.smil", "corpus/smil/bestdpf__xface-new/Faps/actionOnlySeq.smil"})
    expect_program_dump("smil", input);
}

// Greta references (docs/bml.md, "Greta references"): SEMAINE's faces named affect=... with
// their expressivity, through greta_references.tsv and intentions.tsv.
TEST(ReaderTimelines, BmlGreta) {
  expect_program_dump("bml", "corpus/bml/SEMAINE__SEMAINE-3.1/fluent_expressions.xml");
}

// BML blocks given in order (docs/bml.md, "Several blocks"): MERGE, APPEND and REPLACE placed.
TEST(ReaderTimelines, BmlSequence) {
  for (const char* input : {"corpus/bml/sequence/session.bmlseq", "corpus/bml/sequence/greet.bml"})
    expect_program_dump(fs::path(input).extension() == ".bml" ? "bml" : "bmlseq", input);
}

// BML 1.0 reference documents (saiba/OpenBMLParser's tests, docs/bml.md): a chain of offsets
// (h1 to h4 at 4, 6, 8 and 10 s, as the document's comment requires), a nod held from 3 to 5 s with
// a gesture at its stroke (timing only), a gaze straight ahead ready at 3 s and ending at 10 s.
TEST(ReaderTimelines, Bml10Reference) {
  for (const char* input :
       {"corpus/bml/saiba__OpenBMLParser/testoffsetchain.xml", "corpus/bml/saiba__OpenBMLParser/testnodandbeat.xml",
        "corpus/bml/saiba__OpenBMLParser/testgazereadytimed.xml"})
    expect_program_dump("bml", input);
}

// SmartBody (docs/bml.md, "SmartBody"): recorded speech's lips rows as one viseme track.
TEST(ReaderTimelines, BmlSmartBody) { expect_program_dump("bml", "corpus/bml/worldforge__smartbody/good.bml"); }

TEST(ReaderTimelines, Fap) {
  for (const char* input : {"corpus/examples/fap/greta-lips.fap", "corpus/examples/fap/semaine-stamps.fap",
                            "corpus/examples/fap/vreng-joy.fap", "corpus/examples/xmto/parts/blink.fap"}) {
    const auto fap = read_fap_text(read_bytes(input), input);
    ASSERT_TRUE(fap.ok()) << format_diagnostic(fap.error());
    expect_frames_dump("fap", input, fap->sequence);
  }
}

TEST(ReaderTimelines, Fba) {
  for (const std::string input : {"corpus/fba/vreng-joy.fba", "corpus/fba/time-code-29.97fps.fba"}) {
    const std::string bytes = read_bytes(input);
    const std::span stream(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
    const auto decoded = decode_fba(stream, {.file = input});
    ASSERT_TRUE(decoded.ok()) << format_diagnostic(decoded.error());
    expect_frames_dump("fba", input, decoded->sequence);
  }
}

// The corpus's one MP4 (GPAC's) carries a placeholder FBA stream, so the MP4 read here is the one
// the program writes for a bundled example; the dump is then the .fap example's, through the FBA
// encoder, the MP4 writer and reader and the FBA decoder, and is named after the .fap.
TEST(ReaderTimelines, Mp4) {
  const std::string source = "corpus/examples/fap/vreng-joy.fap";
  const std::string written = test::binary_dir() + "/timeline-golden/vreng-joy.mp4";
  fs::create_directories(fs::path(written).parent_path());
  const test::CommandRun run = test::run_fapc("compile " + source + " -o '" + written + "'");
  ASSERT_EQ(run.exit_status, 0) << run.err;
  const std::string bytes = read_bytes(fs::relative(written, test::source_dir()).string());
  const auto mp4 = mpeg4::read_mp4(mpeg4::Bytes(bytes.begin(), bytes.end()), source);
  ASSERT_TRUE(mp4.ok()) << format_diagnostic(mp4.error());
  const auto track = mpeg4::read_fba_track(*mp4);
  ASSERT_TRUE(track.ok()) << format_diagnostic(track.error());
  const auto decoded = decode_fba(mpeg4::fba_stream_from_track(*track), {.file = source});
  ASSERT_TRUE(decoded.ok()) << format_diagnostic(decoded.error());
  expect_frames_dump("mp4", source, decoded->sequence);
}

// The Algebra of Expressions' result has frames, not a timeline, like the frame inputs: the
// program combines the bundled .combine (its operands are in ../fap, hence --allow-include), the
// .fap it writes is read back (a .fap keeps every value), and its frames are lifted.
TEST(ReaderTimelines, Combine) {
  const std::string source = "corpus/examples/algebra/smiling-mouth-angry-eyes.combine";
  const std::string written = test::binary_dir() + "/timeline-golden/smiling-mouth-angry-eyes.fap";
  fs::create_directories(fs::path(written).parent_path());
  const test::CommandRun run =
      test::run_fapc("compile " + source + " --allow-include corpus/examples -o '" + written + "'");
  ASSERT_EQ(run.exit_status, 0) << run.err;
  const auto fap = read_fap_text(read_bytes(fs::relative(written, test::source_dir()).string()), source);
  ASSERT_TRUE(fap.ok()) << format_diagnostic(fap.error());
  expect_frames_dump("combine", source, fap->sequence);
}

}  // namespace
}  // namespace fapc
