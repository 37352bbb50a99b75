// verify_fba: the encoder checks itself by decoding what it wrote (the libFLAC habit).
#include <cstdlib>
#include <optional>
#include <string>

#include "fapc/codec/codes.hpp"
#include "fapc/codec/fba.hpp"
#include "fba/fba_quant.hpp"
#include "fba/shown_values.hpp"

namespace fapc {

namespace {

Diagnostic failure(ErrorCode code, const std::string& file, const std::string& message) {
  return make_error(code, Location::whole_file(file), "verification failed: " + message);
}

std::string at_frame(const FapFrame& frame) { return "frame " + std::to_string(frame.number) + ": "; }

// Within `tolerance` of each other.
bool close(std::int64_t a, std::int64_t b, std::int64_t tolerance) { return std::llabs(a - b) <= tolerance; }

std::string compare_fields(const FapFrame& in, const FapFrame& out, int quant) {
  // Blends and intensities are quantised by fap_quant itself, and never reconstructed above 63:
  // within half a step of the value, or of the largest legal reconstruction below it.
  const auto near = [quant](int wanted, int got) {
    return close(fba::legal_target(wanted, fba::kLargestFieldValue, quant), got, quant / 2);
  };
  if (in.has(1)) {
    const VisemeFields& a = in.viseme;
    const VisemeFields& b = out.viseme;
    if (a.select1 != b.select1 || a.select2 != b.select2 || a.def != b.def || !near(a.blend, b.blend))
      return "viseme fields differ";
  }
  if (in.has(2)) {
    const ExpressionFields& a = in.expression;
    const ExpressionFields& b = out.expression;
    if (a.select1 != b.select1 || a.select2 != b.select2 || a.init_face != b.init_face || a.def != b.def ||
        !near(a.intensity1, b.intensity1) || !near(a.intensity2, b.intensity2))
      return "expression fields differ";
  }
  return {};
}

// The checks of one frame: the input's frame against the one decoded from it.
class FrameChecks {
 public:
  explicit FrameChecks(const FbaEncodeOptions& options) : options_(options) {}

  // An empty text when the frames agree, else what differs.
  std::string compare(const FapFrame& in, const FapFrame& out) {
    if (!first_number_) first_number_ = in.number;
    if (out.number != in.number - *first_number_)
      return at_frame(in) + "decoded as frame " + std::to_string(out.number);
    const bool masks_differ =
        options_.masks == FbaMaskMode::keep ? out.mask != in.mask : out.has(1) != in.has(1) || out.has(2) != in.has(2);
    if (masks_differ) return at_frame(in) + "the mask differs";
    if (auto differs = compare_fields(in, out, options_.quant); !differs.empty()) return at_frame(in) + differs;
    held_in_.advance(in);
    held_out_.advance(out);
    for (int fap = 3; fap <= kFapCount; ++fap) {
      const std::int64_t tolerance = fba_tolerance(fap, options_.quant);
      const FapInfo& info = fap_table()[static_cast<std::size_t>(fap - 1)];
      const std::int64_t step = static_cast<std::int64_t>(info.quant_step) * options_.quant;
      const auto check = [&](std::int64_t got, std::int64_t wanted, const char* player) -> std::string {
        if (close(got, fba::legal_target(wanted, info.legal_max(), step), tolerance)) return {};
        return at_frame(in) + "FAP " + std::to_string(fap) + " (" + std::string(info.name) + ") decoded " +
               std::to_string(got) + ", encoded " + std::to_string(wanted) + " (tolerance " +
               std::to_string(tolerance) + ", as " + player + " shows it)";
      };
      for (const std::string& differs :
           {check(fba::shown_as_zero(out, fap), fba::shown_as_zero(in, fap), "a player that shows absent FAPs at 0"),
            check(held_out_.held(fap), held_in_.held(fap), "a player that holds absent FAPs"),
            check(fba::shown_with_partner(out, fap), fba::shown_with_partner(in, fap),
                  "the reference decoder, which copies a FAP into its absent partner,")})
        if (!differs.empty()) return differs;
    }
    return {};
  }

 private:
  const FbaEncodeOptions& options_;
  std::optional<std::int64_t> first_number_;
  fba::HeldValues held_in_, held_out_;
};

}  // namespace

Status verify_fba(std::size_t count, int fps, const FbaInputFrames& next, const EncodedFba& encoded,
                  const FbaEncodeOptions& options, const std::string& file) {
  FbaDecodeOptions decode_options;
  decode_options.file = file;
  // First decoding: each frame checked against the input's (the first difference is reported only
  // once the counts are known to agree, as they are checked first) and checked by the encoder
  // that codes the decoded frames again.
  FrameChecks checks(options);
  std::size_t decoded_frames = 0;
  std::string first_difference;
  FbaEncoder again(options);
  std::optional<Diagnostic> again_error;
  auto decoded = decode_fba(encoded.bytes, decode_options, [&](const FapFrame& out) {
    if (decoded_frames++ < count && first_difference.empty()) first_difference = checks.compare(next(), out);
    if (!again_error)
      if (auto status = again.check(out); !status) again_error = status.error();
    return ok_status();
  });
  if (!decoded)
    return failure(codes::verify::fba_does_not_decode, file,
                   "the stream does not decode: " + format_diagnostic(decoded.error()));
  if (decoded_frames != count)
    return failure(codes::verify::fba_differs, file,
                   std::to_string(decoded_frames) + " frames decoded, " + std::to_string(count) + " encoded");
  // The rate travels in intra planes, so a stream without planes has none.
  if (count > 0 && decoded->sequence.fps != fps)
    return failure(
        codes::verify::fba_differs, file,
        "frame rate " + std::to_string(decoded->sequence.fps) + " decoded, " + std::to_string(fps) + " encoded");
  if (!first_difference.empty()) return failure(codes::verify::fba_differs, file, first_difference);
  // Second decoding: the frames coded again (as encode_fba would: the rate first, then every
  // frame checked, then added), and the bytes compared.
  const auto not_again = [&](const Diagnostic& error) {
    return failure(codes::verify::fba_differs, file, "the decoded frames do not encode again: " + error.message);
  };
  if (auto started = again.start(decoded->sequence.fps); !started) return not_again(started.error());
  if (again_error) return not_again(*again_error);
  auto redecoded = decode_fba(encoded.bytes, decode_options, [&](const FapFrame& out) {
    if (!again_error)
      if (auto status = again.add(out); !status) again_error = status.error();
    return ok_status();
  });
  if (!redecoded)
    return failure(codes::verify::fba_does_not_decode, file,
                   "the stream does not decode: " + format_diagnostic(redecoded.error()));
  if (again_error) return not_again(*again_error);
  auto bytes = again.finish();
  if (!bytes) return not_again(bytes.error());
  if (bytes->bytes != encoded.bytes) {
    std::size_t at = 0;
    while (at < bytes->bytes.size() && at < encoded.bytes.size() && bytes->bytes[at] == encoded.bytes[at]) ++at;
    return failure(codes::verify::fba_differs, file,
                   "re-encoding the decoded frames gives different bytes from byte " + std::to_string(at));
  }
  return ok_status();
}

Status verify_fba(const FapSequence& input, const EncodedFba& encoded, const FbaEncodeOptions& options,
                  const std::string& file) {
  std::size_t k = 0;
  return verify_fba(
      input.frames.size(), input.fps, [&]() -> const FapFrame& { return input.frames[k++]; }, encoded, options, file);
}

}  // namespace fapc
