// encode_fba and FbaEncoder: check the input, then let the planner decide and the plane writer
// write, one group of planes at a time.
#include <optional>
#include <string>

#include "fapc/codec/codes.hpp"
#include "fapc/codec/fba.hpp"
#include "fba/gop_planner.hpp"
#include "fba/mask_fitter.hpp"
#include "fba/plane_writer.hpp"

namespace fapc {

namespace {

// Longer gaps would cost 4 bits per 15 frames for nothing; a gap this long is a broken input.

// An error about FAP `fap` of `frame`, placed where the caller says the frame came from.
Diagnostic input_error(ErrorCode code, const FbaEncodeOptions& options, const FapFrame& frame, int fap,
                       const std::string& message) {
  return make_error(code, options.locate ? options.locate(frame.number, fap) : Location{},
                    "frame " + std::to_string(frame.number) + ": " + message);
}

std::string outside(const char* field, int value, int high) {
  return std::string(field) + " is " + std::to_string(value) + ", outside 0.." + std::to_string(high);
}

Status check_fields(const FbaEncodeOptions& options, const FapFrame& f) {
  struct Field {
    int fap;
    bool present;
    const char* name;
    int value, high;
  };
  const Field fields[] = {
      {1, f.has(1), "viseme_select1", f.viseme.select1, 14},
      {1, f.has(1), "viseme_select2", f.viseme.select2, 14},
      {1, f.has(1), "viseme_blend", f.viseme.blend, 63},
      {1, f.has(1), "viseme_def", f.viseme.def, 1},
      {2, f.has(2), "expression_select1", f.expression.select1, 6},
      {2, f.has(2), "expression_intensity1", f.expression.intensity1, 63},
      {2, f.has(2), "expression_select2", f.expression.select2, 6},
      {2, f.has(2), "expression_intensity2", f.expression.intensity2, 63},
      {2, f.has(2), "init_face", f.expression.init_face, 1},
      {2, f.has(2), "expression_def", f.expression.def, 1},
  };
  for (const Field& field : fields)
    if (field.present && (field.value < 0 || field.value > field.high))
      return input_error(codes::fba::field_out_of_range, options, f, field.fap,
                         outside(field.name, field.value, field.high));
  return ok_status();
}

Status check_options(const FbaEncodeOptions& options) {
  if (options.quant < 0 || options.quant > fba::kMaxFapQuant)
    return make_error(codes::fba::bad_quant, Location{},
                      "fap_quant must be 0..31, not " + std::to_string(options.quant));
  if (options.intra_period < 0)
    return make_error(codes::fba::bad_intra_period, Location{}, "the intra period must not be negative");
  return ok_status();
}

Status check_rate(int fps) {
  if (fps < 1 || fps >= (1 << fba::kFrameRateBits))
    return make_error(
        codes::fba::frame_rate_not_codable, Location{},
        "frame rate " + std::to_string(fps) + " cannot be coded (the stream carries 1 to 255 frames per second)");
  return ok_status();
}

}  // namespace

struct FbaEncoder::State {
  explicit State(const FbaEncodeOptions& chosen)
      : options(chosen), setup(check_options(chosen)), planner(window, chosen) {
    if (chosen.masks == FbaMaskMode::fit) masks.emplace(chosen.quant);
  }

  // Writes every group the window completes; `input_ended` lets the last one end at the window's end.
  Status write_groups(bool input_ended) {
    for (;;) {
      auto gop = planner.next(input_ended);
      if (!gop) return gop.error();
      if (!*gop) return ok_status();
      writer->write(**gop);
      window.erase_front((*gop)->end);
    }
  }

  FbaEncodeOptions options;
  Status setup;
  // First pass.
  std::optional<fba::MaskPlanner> masks;
  std::int64_t first_number = 0, previous_number = 0;
  std::size_t checked = 0;
  // Second pass.
  std::optional<fba::MaskFitter> fitter;
  std::size_t added = 0;
  fba::FrameWindow window;  // one group of frames as coded, and the frame after it, packed
  fba::GopPlanner planner;
  std::optional<fba::PlaneWriter> writer;  // from start()
};

FbaEncoder::FbaEncoder(const FbaEncodeOptions& options) : state_(std::make_unique<State>(options)) {}
FbaEncoder::~FbaEncoder() = default;
FbaEncoder::FbaEncoder(FbaEncoder&&) noexcept = default;
FbaEncoder& FbaEncoder::operator=(FbaEncoder&&) noexcept = default;

Status FbaEncoder::start(int fps) {
  State& s = *state_;
  if (!s.setup) return s.setup;
  if (auto status = check_rate(fps); !status) return status;
  if (!s.writer) s.writer.emplace(s.window, fps, s.options);
  return ok_status();
}

Status FbaEncoder::check(const FapFrame& frame) {
  State& s = *state_;
  if (!s.setup) return s.setup;
  if (s.checked == 0) s.first_number = frame.number;
  if (s.checked > 0) {
    if (frame.number - s.previous_number - 1 < 0)
      return input_error(codes::fba::frames_not_ascending, s.options, frame, 0, "frame numbers must ascend");
    // Gaps cost 4 bits per 15 skipped frames; the span bounds them all.
    if (frame.number - s.first_number >= s.options.max_frames) {
      Limits limits;
      limits.max_frames = s.options.max_frames;
      return limit_error(Location{},
                         "frames " + std::to_string(s.first_number) + " to " + std::to_string(frame.number) + " span " +
                             std::to_string(frame.number - s.first_number + 1) + " frames",
                         Limit::frames, limits);
    }
  }
  if (auto status = check_fields(s.options, frame); !status) return status;
  s.previous_number = frame.number;
  ++s.checked;
  if (s.masks) s.masks->add(frame);
  return ok_status();
}

Status FbaEncoder::add(const FapFrame& frame) {
  State& s = *state_;
  if (!s.setup) return s.setup;
  if (!s.writer) return make_error(codes::fba::encoder_misuse, Location{}, "FbaEncoder: a frame added before start()");
  if (s.added >= s.checked)
    return make_error(codes::fba::encoder_misuse, Location{},
                      "FbaEncoder: a frame added that the first pass did not check");
  if (s.masks && !s.fitter) s.fitter.emplace(std::move(*s.masks).finish());
  if (s.added == 0) s.writer->reserve(s.checked);  // a plane a frame
  ++s.added;
  if (s.fitter) {
    FapFrame coded = frame;
    s.fitter->fit(coded);
    s.window.push_back(coded);
  } else {
    s.window.push_back(frame);
  }
  return s.write_groups(false);
}

Result<EncodedFba> FbaEncoder::finish() {
  State& s = *state_;
  if (!s.setup) return s.setup.error();
  if (!s.writer) return make_error(codes::fba::encoder_misuse, Location{}, "FbaEncoder: finished before start()");
  if (s.added != s.checked)
    return make_error(codes::fba::encoder_misuse, Location{},
                      "FbaEncoder: the second pass added fewer frames than the first checked");
  if (auto status = s.write_groups(true); !status) return status.error();
  return s.writer->finish();
}

Result<EncodedFba> encode_fba(const FapSequence& sequence, const FbaEncodeOptions& options) {
  FbaEncoder encoder(options);
  if (auto status = encoder.start(sequence.fps); !status) return status.error();
  for (const FapFrame& frame : sequence.frames)
    if (auto status = encoder.check(frame); !status) return status.error();
  for (const FapFrame& frame : sequence.frames)
    if (auto status = encoder.add(frame); !status) return status.error();
  return encoder.finish();
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
