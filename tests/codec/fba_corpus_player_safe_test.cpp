// Issue 17's sweep: every .fap file of the corpus at fap_quant 1, 2, 4 and 8 under five option
// sets (none, --ranges max, --intra-period 25, --masks keep, --align-planes). In every stream no
// start code follows more than 8 zero bits, the reference decoder's end-of-stream look never
// lands on the end code before the last plane, no decoded field leaves its legal range, and the
// stream verifies (values within half a step, re-encoding identical). The counts are printed and
// recorded as test properties. The sanitizer build (FAPC_SANITIZED_BUILD) sweeps every eighth
// file only, to stay inside CI's time budget (docs/testing.md).
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>

#include "fapc/codec/fap_file.hpp"
#include "fapc/codec/fba.hpp"
#include "stream_property_checks.hpp"
#include "support/corpus_sweep.hpp"

namespace fapc {
namespace {

struct OptionSet {
  const char* name;
  FbaEncodeOptions options;
};

std::vector<OptionSet> option_sets(int quant) {
  std::vector<OptionSet> sets(5);
  sets[0].name = "none";
  sets[1].name = "--ranges max";
  sets[1].options.ranges = FbaRangeMode::max;
  sets[2].name = "--intra-period 25";
  sets[2].options.intra_period = 25;
  sets[3].name = "--masks keep";
  sets[3].options.masks = FbaMaskMode::keep;
  sets[4].name = "--align-planes";
  sets[4].options.align_planes = true;
  for (OptionSet& set : sets) set.options.quant = quant;
  return sets;
}

// The largest |value| of each FAP 3..68 in the input: a FAP never above its legal range there
// must never be decoded above it.
std::array<std::int64_t, kFapCount> largest_values(const FapSequence& sequence) {
  std::array<std::int64_t, kFapCount> largest{};
  for (const FapFrame& frame : sequence.frames)
    for (int fap = 3; fap <= kFapCount; ++fap)
      if (frame.has(fap)) {
        auto& l = largest[static_cast<std::size_t>(fap - 1)];
        l = std::max<std::int64_t>(l, std::llabs(frame.value(fap)));
      }
  return largest;
}

TEST(FbaCorpusPlayerSafe, EveryStreamIsReadTheSameByTheReferenceDecoder) {
  ASSERT_GE(test::all_good_corpus_fap_files().size(), 196u);
  const auto files = test::sweep_fap_files();
  std::size_t streams = 0, refused = 0, start_codes = 0, fields = 0, values = 0, files_swept = 0, padded = 0,
              planes = 0;
  for (const std::string& path : files) {
    auto read = read_fap_text(test::read_text(path), path);
    ASSERT_TRUE(read.ok()) << path;
    ++files_swept;
    const auto largest = largest_values(read->sequence);
    for (const int quant : {1, 2, 4, 8}) {
      for (const OptionSet& set : option_sets(quant)) {
        const std::string label = path + " at fap_quant " + std::to_string(quant) + " with " + set.name;
        auto encoded = encode_fba(read->sequence, set.options);
        if (!encoded.ok()) {  // a value beyond the widest range at this fap_quant: refused, counted
          EXPECT_NE(encoded.error().message.find("beyond the largest range"), std::string::npos) << label;
          ++refused;
          continue;
        }
        ++streams;
        const auto& bytes = encoded->bytes;
        const auto runs = test::zeros_before_start_codes(bytes);
        start_codes += runs.size();
        for (const std::size_t run : runs) EXPECT_LE(run, 8u) << label;
        // Planes that carry an empty skip count: where the encoder moved a plane's end.
        planes += encoded->planes.size();
        for (const CodedPlane& plane : encoded->planes) {
          const auto skip = test::read_skip_field(bytes, plane.bit_offset, set.options.align_planes);
          padded += skip.flag == 1 && skip.chunks == std::vector<int>{0};
        }
        if (!encoded->planes.empty()) {
          EXPECT_FALSE(test::reference_drops_last_plane(bytes, encoded->planes.back().bit_offset)) << label;
        }
        auto decoded = decode_fba(bytes);
        ASSERT_TRUE(decoded.ok()) << label;
        for (const FapFrame& frame : decoded->sequence.frames) {
          if (frame.has(1)) {
            EXPECT_TRUE(test::field_shown_as_is(frame.viseme.blend, quant)) << label;
            ++fields;
          }
          if (frame.has(2)) {
            EXPECT_TRUE(test::field_shown_as_is(frame.expression.intensity1, quant)) << label;
            EXPECT_TRUE(test::field_shown_as_is(frame.expression.intensity2, quant)) << label;
            fields += 2;
          }
          for (int fap = 3; fap <= kFapCount; ++fap) {
            if (!frame.has(fap)) continue;
            const auto i = static_cast<std::size_t>(fap - 1);
            const std::int64_t legal = fap_table()[i].legal_max();
            if (largest[i] <= legal) {
              EXPECT_LE(std::llabs(frame.value(fap)), legal) << label << " FAP " << fap;
            }
            ++values;
          }
        }
        const Status verified = verify_fba(read->sequence, *encoded, set.options, path);
        EXPECT_TRUE(verified.ok()) << label << ": " << (verified.ok() ? "" : format_diagnostic(verified.error()));
      }
    }
  }
  std::printf(
      "swept %zu files: %zu streams (%zu refused as beyond the widest range), %zu start codes after the "
      "object start code, %zu of %zu planes ended later by an empty skip count, %zu decoded blends and "
      "intensities, %zu decoded FAP values\n",
      files_swept, streams, refused, start_codes, padded, planes, fields, values);
  RecordProperty("files", static_cast<int>(files_swept));
  RecordProperty("streams", static_cast<int>(streams));
  RecordProperty("refused", static_cast<int>(refused));
  RecordProperty("start_codes", static_cast<int>(start_codes));
  RecordProperty("padded_planes", static_cast<int>(padded));
}

}  // namespace
}  // namespace fapc
