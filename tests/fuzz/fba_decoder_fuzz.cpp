// libFuzzer target: the FBA decoder must never crash or read out of bounds, whatever the bytes.
// When it accepts a stream, the frames it returns must survive the encoder: if they encode (at
// the stream's first fap_quant), verify_fba must hold, i.e. the new stream decodes to them within
// tolerance and re-encodes to the same bytes. A failure there is an encoder or decoder bug.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <span>

#include "fapc/codec/fba.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fapc::FbaDecodeOptions decode_options;
  decode_options.file = "fuzz.fba";
  decode_options.max_frames = 100000;
  auto decoded = fapc::decode_fba(std::span<const std::uint8_t>(data, size), decode_options);
  if (!decoded) {
    // Every error points into the input (or just past its end, for a truncated stream).
    const std::int64_t at = decoded.error().where.byte_offset;
    if (at < 0 || at > static_cast<std::int64_t>(size)) std::abort();
    return 0;
  }
  fapc::FbaEncodeOptions options;
  if (!decoded->info.intra_planes.empty()) options.quant = decoded->info.intra_planes.front().fap_quant;
  auto encoded = fapc::encode_fba(decoded->sequence, options);
  if (!encoded) return 0;  // values or a frame rate the encoder refuses, with an error
  if (auto verified = fapc::verify_fba(decoded->sequence, *encoded, options, "again.fba"); !verified) {
    std::fprintf(stderr, "%s\n", fapc::format_diagnostic(verified.error()).c_str());
    std::abort();
  }
  return 0;
}
