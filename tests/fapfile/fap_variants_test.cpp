// The synthetic variant files of corpus/fap-variants/ (no real sample exists for them).
#include <gtest/gtest.h>

#include "fapc/codec/fap_file.hpp"
#include "fapc/codec/file_io.hpp"
#include "support/test_support.hpp"

namespace fapc {
namespace {

FapReadResult read_variant(const std::string& name, const FapReadOptions& options = {}) {
  const std::string path = test::corpus_dir() + "/fap-variants/" + name;
  auto read = read_fap_text(test::read_text(path), path, options);
  EXPECT_TRUE(read.ok()) << (read.ok() ? "" : format_diagnostic(read.error()));
  return read.ok() ? std::move(*read) : FapReadResult{};
}

TEST(FapVariants, CommentsAroundTheHeaderAndNoActiveFap) {
  const FapReadResult r = read_variant("v05-comments-around-header.fap");
  EXPECT_EQ(r.facts.comment_lines, 2);
  EXPECT_TRUE(r.facts.zero_active_faps);
  ASSERT_EQ(r.sequence.frames.size(), 1u);
  EXPECT_TRUE(r.sequence.frames[0].mask.none());
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_EQ(format_diagnostic(r.warnings[0]),
            test::corpus_dir() +
                "/fap-variants/v05-comments-around-header.fap:3:1: warning: "
                "comment line after the header (Xface and Greta's Java reader cannot read it)");
}

TEST(FapVariants, VisemeAndExpressionWithAllTheirFields) {
  const FapReadResult r = read_variant("v10-fap12-full-fields.fap");
  EXPECT_TRUE(r.facts.fap12_full_fields);
  EXPECT_FALSE(r.facts.fap12_single_values);
  ASSERT_EQ(r.sequence.frames.size(), 2u);
  const FapFrame& f = r.sequence.frames[1];
  EXPECT_EQ(f.viseme, (VisemeFields{10, 11, 32, 1}));
  EXPECT_EQ(f.expression, (ExpressionFields{3, 63, 6, 20, 1, 0}));
  EXPECT_EQ(f.value(3), -45);
  // Written back in the same 4/6 form.
  EXPECT_NE(write_fap_text(r.sequence).find("\n1 10 11 32 1 3 63 6 20 1 0 -45 \n"), std::string::npos);
}

TEST(FapVariants, Vreng20WithTabsFramesFromOneAndCrlf) {
  const FapReadResult r = read_variant("v13-vreng-2.0-tabs-from-one.fap");
  EXPECT_EQ(r.facts.version, "2.0");
  EXPECT_TRUE(r.facts.tabs);
  EXPECT_TRUE(r.facts.crlf);
  EXPECT_TRUE(r.facts.frames_from_one);
  EXPECT_EQ(r.sequence.fps, 10);
  ASSERT_EQ(r.sequence.frames.size(), 3u);
  EXPECT_EQ(r.sequence.frames[0].number, 0);
  EXPECT_EQ(r.sequence.frames[1].value(48), 7716);  // kept as written by default
  FapReadOptions divide;
  divide.vreng_divide_v20 = true;
  const FapReadResult d = read_variant("v13-vreng-2.0-tabs-from-one.fap", divide);
  EXPECT_EQ(d.sequence.frames[1].value(48), 386);  // 7716 / 20 = 385.8, rounded
}

TEST(FapVariants, FloatValuesRoundHalfAwayFromZero) {
  const FapReadResult r = read_variant("v17-float-values.fap");
  EXPECT_TRUE(r.facts.float_values);
  ASSERT_EQ(r.sequence.frames.size(), 2u);
  EXPECT_EQ(r.sequence.frames[0].value(3), 11);   // 10.5
  EXPECT_EQ(r.sequence.frames[0].value(48), -3);  // -2.5
  EXPECT_EQ(r.sequence.frames[1].value(3), 11);   // 11.49
  EXPECT_EQ(r.warnings.size(), 1u);               // once per file
}

TEST(FapVariants, EmptyFileAndHeaderOnly) {
  const FapReadResult empty = read_variant("empty.fap");
  EXPECT_TRUE(empty.sequence.frames.empty());
  EXPECT_FALSE(empty.facts.has_header);
  const FapReadResult header = read_variant("header-only.fap");
  EXPECT_TRUE(header.sequence.frames.empty());
  EXPECT_EQ(header.facts.header_count, 0);
}

TEST(FapVariants, ByteOrderMarkBlankLinesAndAbsentFrames) {
  const FapReadResult r = read_variant("bom-blank-lines-gaps.fap");
  EXPECT_TRUE(r.facts.utf8_bom);
  EXPECT_TRUE(r.facts.frame_gaps);
  ASSERT_EQ(r.sequence.frames.size(), 3u);
  EXPECT_EQ(r.sequence.frames[1].number, 3);
  // Written with frames 0..4: the absent frames 1 and 2 hold frame 0's values.
  const std::string written = write_fap_text(r.sequence);
  EXPECT_EQ(written.substr(0, written.find('\n')), "2.1 gaps 25 5");
  EXPECT_NE(written.find("\n2 5 \n"), std::string::npos);
  EXPECT_NE(written.find("\n3 8 \n"), std::string::npos);
}

TEST(FapVariants, SemaineTimeStampsBecomeFrames) {
  const std::string path = test::corpus_dir() + "/fap/SEMAINE__SEMAINE-3.1/example2.v4ebe70d.fap";
  auto r = read_fap_text(test::read_text(path), path);
  ASSERT_TRUE(r.ok());
  EXPECT_TRUE(r->facts.semaine_time_line);
  EXPECT_TRUE(r->facts.millisecond_stamps);
  EXPECT_FALSE(r->facts.final_newline);
  EXPECT_EQ(r->sequence.fps, 25);
  EXPECT_EQ(r->sequence.frames.front().number, 0);
  EXPECT_EQ(r->sequence.frames.back().number, 19);
}

TEST(FapVariants, GzipRoundTrip) {
  FapSequence seq;
  seq.name = "gz";
  FapFrame f;
  f.set(3, 100);
  seq.frames.push_back(f);
  const std::string path = test::binary_dir() + "/gzip-round-trip.fap.gz";
  ASSERT_TRUE(write_file_atomic(path, write_fap_text(seq)).ok());
  auto bytes = read_file_bytes(path);
  ASSERT_TRUE(bytes.ok());
  EXPECT_EQ(*bytes, write_fap_text(seq));
}

}  // namespace
}  // namespace fapc
