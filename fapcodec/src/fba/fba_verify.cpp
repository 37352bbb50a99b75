// verify_fba: the encoder checks itself by decoding what it wrote (the libFLAC habit).
#include <cstdlib>
#include <string>

#include "fapc/codec/fba.hpp"
#include "fba/fba_quant.hpp"
#include "fba/shown_values.hpp"

namespace fapc {

namespace {

Diagnostic failure(const std::string& file, const std::string& message) {
  return make_error(ErrorKind::verification_failed, Location{file, 0, 0, -1}, "verification failed: " + message);
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

}  // namespace

Status verify_fba(const FapSequence& input, const EncodedFba& encoded, const FbaEncodeOptions& options,
                  const std::string& file) {
  FbaDecodeOptions decode_options;
  decode_options.file = file;
  auto decoded = decode_fba(encoded.bytes, decode_options);
  if (!decoded) return failure(file, "the stream does not decode: " + format_diagnostic(decoded.error()));
  const auto& in = input.frames;
  const auto& out = decoded->sequence.frames;
  if (in.size() != out.size())
    return failure(file, std::to_string(out.size()) + " frames decoded, " + std::to_string(in.size()) + " encoded");
  // The rate travels in intra planes, so a stream without planes has none.
  if (!in.empty() && decoded->sequence.fps != input.fps)
    return failure(file, "frame rate " + std::to_string(decoded->sequence.fps) + " decoded, " +
                             std::to_string(input.fps) + " encoded");
  fba::HeldValues held_in, held_out;
  for (std::size_t k = 0; k < in.size(); ++k) {
    if (out[k].number != in[k].number - in.front().number)
      return failure(file, at_frame(in[k]) + "decoded as frame " + std::to_string(out[k].number));
    const bool masks_differ = options.masks == FbaMaskMode::keep ? out[k].mask != in[k].mask
                                                                 : out[k].has(1) != in[k].has(1) || out[k].has(2) != in[k].has(2);
    if (masks_differ) return failure(file, at_frame(in[k]) + "the mask differs");
    if (auto differs = compare_fields(in[k], out[k], options.quant); !differs.empty())
      return failure(file, at_frame(in[k]) + differs);
    held_in.advance(in[k]);
    held_out.advance(out[k]);
    for (int fap = 3; fap <= kFapCount; ++fap) {
      const std::int64_t tolerance = fba_tolerance(fap, options.quant);
      const FapInfo& info = fap_table()[static_cast<std::size_t>(fap - 1)];
      const std::int64_t step = static_cast<std::int64_t>(info.quant_step) * options.quant;
      const auto check = [&](std::int64_t got, std::int64_t wanted, const char* player) -> std::string {
        if (close(got, fba::legal_target(wanted, info.legal_max(), step), tolerance)) return {};
        return at_frame(in[k]) + "FAP " + std::to_string(fap) + " (" +
               std::string(fap_table()[static_cast<std::size_t>(fap - 1)].name) + ") decoded " +
               std::to_string(got) + ", encoded " + std::to_string(wanted) + " (tolerance " +
               std::to_string(tolerance) + ", as " + player + " shows it)";
      };
      for (const std::string& differs :
           {check(fba::shown_as_zero(out[k], fap), fba::shown_as_zero(in[k], fap), "a player that shows absent FAPs at 0"),
            check(held_out.held(fap), held_in.held(fap), "a player that holds absent FAPs"),
            check(fba::shown_with_partner(out[k], fap), fba::shown_with_partner(in[k], fap),
                  "the reference decoder, which copies a FAP into its absent partner,")})
        if (!differs.empty()) return failure(file, differs);
    }
  }
  auto again = encode_fba(decoded->sequence, options);
  if (!again) return failure(file, "the decoded frames do not encode again: " + again.error().message);
  if (again->bytes != encoded.bytes) {
    std::size_t at = 0;
    while (at < again->bytes.size() && at < encoded.bytes.size() && again->bytes[at] == encoded.bytes[at]) ++at;
    return failure(file, "re-encoding the decoded frames gives different bytes from byte " + std::to_string(at));
  }
  return ok_status();
}

}  // namespace fapc
