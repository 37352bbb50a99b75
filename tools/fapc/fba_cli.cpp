#include "fapc/fba_cli.hpp"

#include "fapc/codec/file_io.hpp"

namespace fapc::cli {

namespace {

// --quant, --intra-period, --ranges fit|max and --masks fit|keep (values already checked by
// convert_options).
FbaEncodeOptions fba_encode_options(const ConvertOptions& options) {
  FbaEncodeOptions fba;
  fba.quant = options.quant;
  fba.intra_period = options.intra_period;
  fba.ranges = options.ranges == "max" ? FbaRangeMode::max : FbaRangeMode::fit;
  fba.masks = options.masks == "keep" ? FbaMaskMode::keep : FbaMaskMode::fit;
  fba.max_frames = options.limits.max_frames;
  return fba;
}

}  // namespace

Result<DecodedFba> read_fba_file(const std::string& path, const Limits& limits) {
  auto bytes = read_file_bytes(path, limits);
  if (!bytes) return bytes.error();
  FbaDecodeOptions options;
  options.file = path;
  options.max_frames = limits.max_frames;
  const auto* data = reinterpret_cast<const std::uint8_t*>(bytes->data());
  return decode_fba(std::span<const std::uint8_t>(data, bytes->size()), options);
}

Result<EncodedFba> encode_checked(const FapSequence& sequence, const ConvertOptions& options, const std::string& input,
                                  bool align_planes) {
  FbaEncodeOptions fba = fba_encode_options(options);
  fba.align_planes = align_planes;
  auto encoded = encode_fba(sequence, fba);
  if (!encoded) {
    Diagnostic error = encoded.error();
    error.where.file = input;
    return error;
  }
  if (options.verify)
    if (auto verified = verify_fba(sequence, *encoded, fba, input); !verified) return verified.error();
  return encoded;
}

}  // namespace fapc::cli
