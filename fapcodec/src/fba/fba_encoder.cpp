// encode_fba: checks the input, then lets the planner decide and the plane writer write.
#include <string>

#include "fapc/codec/fba.hpp"
#include "fba/gop_planner.hpp"
#include "fba/mask_fitter.hpp"
#include "fba/plane_writer.hpp"

namespace fapc {

namespace {

// Longer gaps would cost 4 bits per 15 frames for nothing; a gap this long is a broken input.

Diagnostic input_error(const FapFrame& frame, const std::string& message) {
  return make_error(Location{}, "frame " + std::to_string(frame.number) + ": " + message);
}

std::string outside(const char* field, int value, int high) {
  return std::string(field) + " is " + std::to_string(value) + ", outside 0.." + std::to_string(high);
}

Status check_fields(const FapFrame& f) {
  struct Field {
    bool present;
    const char* name;
    int value, high;
  };
  const Field fields[] = {
      {f.has(1), "viseme_select1", f.viseme.select1, 14},
      {f.has(1), "viseme_select2", f.viseme.select2, 14},
      {f.has(1), "viseme_blend", f.viseme.blend, 63},
      {f.has(1), "viseme_def", f.viseme.def, 1},
      {f.has(2), "expression_select1", f.expression.select1, 6},
      {f.has(2), "expression_intensity1", f.expression.intensity1, 63},
      {f.has(2), "expression_select2", f.expression.select2, 6},
      {f.has(2), "expression_intensity2", f.expression.intensity2, 63},
      {f.has(2), "init_face", f.expression.init_face, 1},
      {f.has(2), "expression_def", f.expression.def, 1},
  };
  for (const Field& field : fields)
    if (field.present && (field.value < 0 || field.value > field.high))
      return input_error(f, outside(field.name, field.value, field.high));
  return ok_status();
}

Status check_input(const FapSequence& sequence, const FbaEncodeOptions& options) {
  if (options.quant < 0 || options.quant > fba::kMaxFapQuant)
    return make_error(Location{}, "fap_quant must be 0..31, not " + std::to_string(options.quant));
  if (options.intra_period < 0)
    return make_error(Location{}, "the intra period must not be negative");
  if (sequence.fps < 1 || sequence.fps >= (1 << fba::kFrameRateBits))
    return make_error(Location{}, "frame rate " + std::to_string(sequence.fps) +
                                      " cannot be coded (the stream carries 1 to 255 frames per second)");
  const auto& frames = sequence.frames;
  for (std::size_t k = 0; k < frames.size(); ++k) {
    if (k > 0) {
      const std::int64_t gap = frames[k].number - frames[k - 1].number - 1;
      if (gap < 0) return input_error(frames[k], "frame numbers must ascend");
      // Gaps cost 4 bits per 15 skipped frames; the span bounds them all.
      if (frames[k].number - frames.front().number >= options.max_frames) {
        Limits limits;
        limits.max_frames = options.max_frames;
        return limit_error(Location{}, "frames " + std::to_string(frames.front().number) + " to " +
                                           std::to_string(frames[k].number) + " span " +
                                           std::to_string(frames[k].number - frames.front().number + 1) + " frames",
                           Limit::frames, limits);
      }
    }
    if (auto status = check_fields(frames[k]); !status) return status;
  }
  return ok_status();
}

}  // namespace

Result<EncodedFba> encode_fba(const FapSequence& sequence, const FbaEncodeOptions& options) {
  if (auto status = check_input(sequence, options); !status) return status.error();
  FapSequence fitted;
  if (options.masks == FbaMaskMode::fit) fitted = {sequence.name, sequence.fps, fba::fit_masks(sequence.frames, options.quant)};
  const FapSequence& coded = options.masks == FbaMaskMode::fit ? fitted : sequence;
  fba::GopPlanner planner(coded, options);
  fba::PlaneWriter writer(coded, options);
  while (planner.has_next()) {
    auto gop = planner.next();
    if (!gop) return gop.error();
    writer.write(*gop);
  }
  return writer.finish();
}

std::array<std::uint8_t, 14> fba_decoder_specific_info() {
  // visual_object_sequence_start_code, profile_and_level_indication; visual_object_start_code,
  // then 0 (no identifier), 0100 (FBA), 011 (stuffing); fba_object_start_code.
  return {0x00, 0x00, 0x01, 0xB0, fba::kSimpleFbaLevel1, 0x00, 0x00, 0x01, 0xB5, 0x23, 0x00, 0x00, 0x01, 0xBA};
}

std::int64_t fba_tolerance(int fap, int quant) {
  return static_cast<std::int64_t>(fap_table()[static_cast<std::size_t>(fap - 1)].quant_step) * quant / 2;
}

}  // namespace fapc
