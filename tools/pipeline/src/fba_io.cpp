#include "fapc/pipeline/fba_io.hpp"

#include <algorithm>

#include "fapc/codec/file_io.hpp"
#include "fapc/mpeg4/mp4_reader.hpp"
#include "fapc/pipeline/codes.hpp"

namespace fapc::pipeline {

namespace {

// The decoder reads the raw stream rebuilt from the track (configuration, one stuffing byte, the
// samples); a byte offset in it is turned back into the file's offset of that sample byte, so an
// error points into the .mp4 the user has.
Diagnostic in_file(Diagnostic d, const mpeg4::Mp4Track& track, const mpeg4::FbaTrackInput& input) {
  if (d.where.byte_offset < 0) return d;
  auto at = static_cast<std::uint64_t>(d.where.byte_offset);
  const std::uint64_t header = input.decoder_specific_info.size() + 1;
  if (at < header) {
    d.where.byte_offset = -1;
    d.message = "FBA decoder configuration, byte " + std::to_string(at) + ": " + d.message;
    return d;
  }
  at -= header;
  for (std::size_t k = 0; k < track.samples.size(); ++k) {
    if (at < track.samples[k].size) {
      d.where.byte_offset = static_cast<std::int64_t>(track.samples[k].offset + at);
      d.message = "FBA track sample " + std::to_string(k + 1) + ": " + d.message;
      return d;
    }
    at -= track.samples[k].size;
  }
  d.where.byte_offset = -1;
  d.message = "end of the FBA track: " + d.message;
  return d;
}

}  // namespace

FbaEncodeOptions fba_encode_options(const ConvertOptions& options) {
  FbaEncodeOptions fba;
  fba.quant = options.quant;
  fba.intra_period = options.intra_period;
  fba.ranges = options.ranges == "max" ? FbaRangeMode::max : FbaRangeMode::fit;
  fba.masks = options.masks == "keep" ? FbaMaskMode::keep : FbaMaskMode::fit;
  fba.max_frames = options.limits.max_frames;
  return fba;
}

Result<DecodedFba> read_fba_file(const std::string& path, const Limits& limits) {
  auto bytes = read_file_bytes(path, limits);
  if (!bytes) return bytes.error();
  FbaDecodeOptions options;
  options.file = path;
  options.max_frames = limits.max_frames;
  const auto* data = reinterpret_cast<const std::uint8_t*>(bytes->data());
  return decode_fba(std::span<const std::uint8_t>(data, bytes->size()), options);
}

std::optional<Diagnostic> fba_rate_error(int fps, const Location& rate_at, int rate_written, const std::string& input) {
  // The stream codes the rate in 8 bits (docs/fba-bitstream.md): a rate outside them is the
  // input's, refused where the input wrote it (or, set by --fps, against the input as a whole).
  if (fps >= 1 && fps <= kMaxFbaFrameRate) return std::nullopt;
  const bool written = !rate_at.file.empty() && rate_written == fps;
  return make_error(codes::fba_output::frame_rate, written ? rate_at : Location::whole_file(input),
                    "frame rate " + std::to_string(fps) + " cannot be coded in an FBA stream (1 to " +
                        std::to_string(kMaxFbaFrameRate) + " frames per second)" +
                        (written ? "" : "; --fps sets another"));
}

std::function<Location(std::int64_t, int)> frame_locator(const std::vector<std::int64_t>& numbers,
                                                         const std::vector<int>& lines, const std::string& input) {
  if (lines.size() != numbers.size()) return {};
  return [&numbers, &lines, &input](std::int64_t number, int) {
    const auto at = std::lower_bound(numbers.begin(), numbers.end(), number);
    if (at == numbers.end() || *at != number) return Location::whole_file(input);
    return Location::text(input, lines[static_cast<std::size_t>(at - numbers.begin())], 1);
  };
}

Result<EncodedFba> encode_checked(const Loaded& loaded, const ConvertOptions& options, const std::string& input,
                                  bool align_planes) {
  const FapSequence& sequence = loaded.frames;
  if (auto error = fba_rate_error(sequence.fps, loaded.rate_at, loaded.rate_written, input)) return *error;
  FbaEncodeOptions fba = fba_encode_options(options);
  fba.align_planes = align_planes;
  // The frames' numbers are gathered only when an error asks where a frame came from.
  if (loaded.frame_lines.size() == sequence.frames.size())
    fba.locate = [&](std::int64_t number, int fap) {
      std::vector<std::int64_t> numbers;
      numbers.reserve(sequence.frames.size());
      for (const FapFrame& frame : sequence.frames) numbers.push_back(frame.number);
      return frame_locator(numbers, loaded.frame_lines, input)(number, fap);
    };
  auto encoded = encode_fba(sequence, fba);
  if (!encoded) {
    Diagnostic error = encoded.error();
    if (error.where.file.empty()) error.where.file = input;
    return error;
  }
  if (options.verify)
    if (auto verified = verify_fba(sequence, *encoded, fba, input); !verified) return verified.error();
  return encoded;
}

mpeg4::FbaTrackView fba_track_view(const EncodedFba& encoded, int fps) {
  const auto dsi = fba_decoder_specific_info();
  mpeg4::FbaTrackView track{mpeg4::Bytes(dsi.begin(), dsi.end()), static_cast<std::uint32_t>(fps), {}};
  track.samples.reserve(encoded.planes.size());
  for (const CodedPlane& plane : encoded.planes)
    track.samples.push_back({std::span<const std::uint8_t>(encoded.bytes).subspan(plane.offset, plane.size),
                             static_cast<std::uint32_t>(plane.frames), plane.intra});
  return track;
}

mpeg4::FbaTrackInput pack_fba_track(const EncodedFba& encoded, int fps) {
  mpeg4::FbaTrackInput track;
  const auto dsi = fba_decoder_specific_info();
  track.decoder_specific_info.assign(dsi.begin(), dsi.end());
  track.timescale = static_cast<std::uint32_t>(fps);
  for (const CodedPlane& plane : encoded.planes) {
    const auto first = encoded.bytes.begin() + static_cast<std::ptrdiff_t>(plane.offset);
    track.samples.push_back(mpeg4::FbaSample{mpeg4::Bytes(first, first + static_cast<std::ptrdiff_t>(plane.size)),
                                             static_cast<std::uint32_t>(plane.frames), plane.intra});
  }
  return track;
}

Result<Mp4Fba> decode_mp4_fba(const mpeg4::Mp4File& mp4, const std::string& path, const Limits& limits) {
  auto track = mpeg4::read_fba_track(mp4);
  if (!track) return track.error();
  FbaDecodeOptions options;
  options.file = path;
  options.max_frames = limits.max_frames;
  auto decoded = decode_fba(mpeg4::fba_stream_from_track(*track), options);
  if (!decoded) return in_file(decoded.error(), *mpeg4::find_fba_track(mp4), *track);
  decoded->warnings.insert(decoded->warnings.begin(), mp4.warnings.begin(), mp4.warnings.end());
  return Mp4Fba{std::move(*track), std::move(*decoded)};
}

Result<Mp4Fba> read_mp4_fba(const std::string& path, const Limits& limits) {
  auto bytes = read_file_bytes(path, limits);
  if (!bytes) return bytes.error();
  auto mp4 = mpeg4::read_mp4(mpeg4::Bytes(bytes->begin(), bytes->end()), path);
  if (!mp4) return mp4.error();
  return decode_mp4_fba(*mp4, path, limits);
}

}  // namespace fapc::pipeline
