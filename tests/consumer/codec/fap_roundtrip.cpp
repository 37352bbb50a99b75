// Reads a .fap file, encodes it losslessly to FBA (written to OUTPUT), decodes that stream and
// checks every frame came back: the codec used from the installed package alone.
#include <cstdio>
#include <span>
#include <string>

#include "fapc/codec/fap_file.hpp"
#include "fapc/codec/fba.hpp"
#include "fapc/codec/file_io.hpp"

namespace {

int fail(const fapc::Diagnostic& error) {
  std::fprintf(stderr, "%s\n", fapc::format_diagnostic(error).c_str());
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: fap_roundtrip INPUT.fap OUTPUT.fba\n");
    return 2;
  }
  const auto text = fapc::read_file_bytes(argv[1]);
  if (!text) return fail(text.error());
  const auto fap = fapc::read_fap_text(*text, argv[1]);
  if (!fap) return fail(fap.error());

  fapc::FbaEncodeOptions options;
  options.quant = 0;                        // lossless
  options.masks = fapc::FbaMaskMode::keep;  // every frame keeps its own mask
  const auto encoded = fapc::encode_fba(fap->sequence, options);
  if (!encoded) return fail(encoded.error());
  const std::string bytes(encoded->bytes.begin(), encoded->bytes.end());
  if (auto written = fapc::write_file_atomic(argv[2], bytes); !written) return fail(written.error());

  const auto decoded = fapc::decode_fba(std::span(encoded->bytes), {.file = argv[2]});
  if (!decoded) return fail(decoded.error());
  const auto& in = fap->sequence.frames;
  const auto& out = decoded->sequence.frames;
  if (in.size() != out.size()) {
    std::fprintf(stderr, "%s: %zu frames in, %zu decoded\n", argv[2], in.size(), out.size());
    return 1;
  }
  for (std::size_t i = 0; i < in.size(); ++i) {
    // The stream numbers frames from its first one.
    const bool same_time = in[i].number - in[0].number == out[i].number - out[0].number;
    if (!same_time || !in[i].same_content(out[i])) {
      std::fprintf(stderr, "%s: frame %zu differs after the round trip\n", argv[2], i);
      return 1;
    }
  }
  std::printf("%s: %zu frames, %zu bytes of FBA, decoded exactly\n", argv[1], in.size(), bytes.size());
  return 0;
}
