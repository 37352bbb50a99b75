#include "fapc/codec/fba.hpp"
#include "fba/stream_reader.hpp"

namespace fapc {

Result<DecodedFba> decode_fba(std::span<const std::uint8_t> bytes, const FbaDecodeOptions& options) {
  fba::StreamReader reader(bytes, options);
  return reader.run();
}

Result<DecodedFba> decode_fba(std::span<const std::uint8_t> bytes, const FbaDecodeOptions& options,
                              const FbaFrameSink& sink) {
  fba::StreamReader reader(bytes, options, sink);
  return reader.run();
}

}  // namespace fapc
