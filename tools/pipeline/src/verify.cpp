// The checks of `fapc verify` (see fapc/pipeline/verify.hpp), including the search for the
// encoder settings a stream was written with.
#include "fapc/pipeline/verify.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <iomanip>
#include <sstream>

#include "fapc/codec/file_io.hpp"
#include "fapc/pipeline/codes.hpp"
#include "fapc/pipeline/fba_io.hpp"
#include "fapc/pipeline/registry.hpp"
#include "verify_streams.hpp"

namespace fapc::pipeline {

namespace {

std::string summary(std::size_t frames, std::size_t bytes, double bits_per_frame, int quant) {
  std::ostringstream out;
  out << frames << " frames, " << bytes << " bytes, " << std::fixed << std::setprecision(1) << bits_per_frame
      << " bits/frame at fap_quant " << quant;
  return out.str();
}

VerifyResult failed(Diagnostic d, Diagnostics warnings = {}) {
  VerifyResult result;
  result.warnings = std::move(warnings);
  result.error = std::move(d);
  return result;
}

VerifyResult passed(std::size_t frames, std::size_t bytes, double bits_per_frame, int quant, Diagnostics warnings) {
  VerifyResult result;
  result.warnings = std::move(warnings);
  result.summary = summary(frames, bytes, bits_per_frame, quant);
  result.frames = frames;
  result.bytes = bytes;
  result.bits_per_frame = bits_per_frame;
  result.quant = quant;
  return result;
}

// The largest difference between what was encoded and what decodes, over FAPs 3-68.
std::optional<long long> max_error(const FapSequence& input, const EncodedFba& encoded) {
  auto decoded = decode_fba(encoded.bytes);
  if (!decoded || decoded->sequence.frames.size() != input.frames.size()) return std::nullopt;
  long long worst = 0;
  for (std::size_t k = 0; k < input.frames.size(); ++k)
    for (int fap = 3; fap <= kFapCount; ++fap)
      if (input.frames[k].has(fap) && decoded->sequence.frames[k].has(fap))
        worst = std::max(worst, std::llabs(static_cast<long long>(input.frames[k].value(fap)) -
                                           static_cast<long long>(decoded->sequence.frames[k].value(fap))));
  return worst;
}

// Plane distances between intra planes that no mask change explains: candidates for the period.
std::vector<int> intra_periods(const FapSequence& frames, const FbaStreamInfo& info) {
  std::vector<int> periods{0};
  std::size_t previous = 0;
  // Intra planes and frames both ascend, so one walk finds every intra plane's frame (a search
  // from the first frame for each made verify grow with the square of the intra planes).
  auto it = frames.frames.begin();
  for (const FbaIntraPlane& intra : info.intra_planes) {
    it = std::find_if(it, frames.frames.end(), [&](const FapFrame& f) { return f.number >= intra.frame; });
    const auto k = it != frames.frames.end() && it->number == intra.frame
                       ? static_cast<std::size_t>(it - frames.frames.begin())
                       : frames.frames.size();
    if (k > 0 && k < frames.frames.size() && frames.frames[k].mask == frames.frames[k - 1].mask)
      periods.push_back(static_cast<int>(k - previous));
    previous = k;
  }
  std::sort(periods.begin() + 1, periods.end());
  periods.erase(std::unique(periods.begin(), periods.end()), periods.end());
  if (periods.size() > 2) periods.resize(2);  // the smallest is the period, or nothing is
  return periods;
}

// Finds the encoder settings that give back what was read: its fap_quant and plane alignment are
// in the stream; the range mode, the intra period and the mask layout are tried in turn, since the
// bits do not say which was used. `same` compares an encoding with the original.
VerifyResult reencode_matches(const std::string& path, const DecodedFba& decoded, bool aligned,
                              const std::function<bool(const EncodedFba&)>& same, std::size_t bytes) {
  const FbaStreamInfo& info = decoded.info;
  const auto failure = [&](const std::string& why) {
    return failed(make_error(codes::verify::fba_foreign, Location::whole_file(path), "verification failed: " + why),
                  decoded.warnings);
  };
  if (info.body_planes > 0) return failure("the stream carries body data, which fapc does not write");
  FbaEncodeOptions options;
  for (const FbaIntraPlane& intra : info.intra_planes) {
    if (&intra != &info.intra_planes.front() && intra.fap_quant != options.quant)
      return failure("fap_quant changes within the stream, which fapc does not do");
    options.quant = intra.fap_quant;
  }
  options.align_planes = aligned;
  for (const FbaMaskMode masks : {FbaMaskMode::fit, FbaMaskMode::keep})
    for (const FbaRangeMode ranges : {FbaRangeMode::fit, FbaRangeMode::max})
      for (const int period : intra_periods(decoded.sequence, info))
        for (const bool listed : {false, true}) {
          options.masks = masks;
          options.ranges = ranges;
          options.intra_period = period;
          options.list_every_mask = listed;
          auto again = encode_fba(decoded.sequence, options);
          if (again && same(*again))
            return passed(decoded.sequence.frames.size(), bytes, info.bits_per_frame(), options.quant,
                          decoded.warnings);
        }
  return failure("re-encoding the decoded frames does not give the same bytes (a stream fapc did not write?)");
}

}  // namespace

VerifyResult verify_fba_file(const std::string& path, const Limits& limits) {
  auto raw = read_file_bytes(path, limits);
  if (!raw) return failed(raw.error());
  const std::vector<std::uint8_t> bytes(raw->begin(), raw->end());
  FbaDecodeOptions decode_options;
  decode_options.file = path;
  decode_options.max_frames = limits.max_frames;
  auto decoded = decode_fba(bytes, decode_options);
  if (!decoded) return failed(decoded.error());
  const FbaStreamInfo& info = decoded->info;
  const bool aligned = info.planes > 0 && info.plane_start_codes == info.planes;
  return reencode_matches(
      path, *decoded, aligned, [&](const EncodedFba& again) { return again.bytes == bytes; }, bytes.size());
}

namespace {

// An MP4's FBA track: each sample must be the plane fapc writes for its frame, with its duration
// and sync flag.
// An .mp4's voice: its presentation (the delay, then the sound) must span the face track's: it
// starts at 0 like every edit list, its sound starts before the face ends, and it ends within one
// frame of the face's end (docs/mp4-and-xmta.md section 1.2). Checked from the container alone.
std::optional<Diagnostic> audio_mismatch(const std::string& path, const mpeg4::Mp4File& mp4,
                                         const mpeg4::FbaTrackInput& fba) {
  const mpeg4::Mp4Track* voice = mpeg4::find_audio_track(mp4);
  if (!voice) return std::nullopt;
  auto audio = mpeg4::read_audio_track(mp4, *voice);
  if (!audio) return audio.error();
  std::uint64_t ticks = 0;
  for (const mpeg4::FbaSample& s : fba.samples) ticks += s.duration;
  const double frame = fba.samples.empty() ? 0.0 : static_cast<double>(fba.samples.front().duration) / fba.timescale;
  const double face_end = static_cast<double>(ticks) / fba.timescale;
  const double start = audio->delay_ms / 1000.0;
  const double end = start + static_cast<double>(audio->length) / audio->sample_rate;
  const auto seconds = [](double v) {
    std::ostringstream s;
    s << std::fixed << std::setprecision(3) << v << " s";
    return s.str();
  };
  const double tolerance = frame + 1e-9;
  std::string why;
  // A voice may start late (its empty edit is part of the track's presentation), but not after the
  // face is over.
  if (start >= face_end)
    why = "the audio track starts at " + seconds(start) + ", after the face track ends at " + seconds(face_end);
  else if (std::abs(end - face_end) > tolerance)
    why = "the audio track ends at " + seconds(end) + ", the face track at " + seconds(face_end);
  if (why.empty()) return std::nullopt;
  return make_error(codes::verify::audio_misaligned, Location::whole_file(path),
                    "verification failed: " + why + " (more than one frame, " + seconds(frame) + ", apart)");
}

}  // namespace

VerifyResult verify_mp4_file(const std::string& path, const Limits& limits) {
  auto raw = read_file_bytes(path, limits);
  if (!raw) return failed(raw.error());
  auto mp4 = mpeg4::read_mp4(mpeg4::Bytes(raw->begin(), raw->end()), path);
  if (!mp4) return failed(mp4.error());
  auto fba = decode_mp4_fba(*mp4, path, limits);
  if (!fba) return failed(fba.error());
  if (auto mismatch = audio_mismatch(path, *mp4, fba->track))
    return failed(std::move(*mismatch), fba->decoded.warnings);
  const std::vector<mpeg4::FbaSample>& samples = fba->track.samples;
  std::size_t bytes = 0;
  for (const mpeg4::FbaSample& sample : samples) bytes += sample.bytes.size();
  const auto same = [&](const EncodedFba& again) {
    if (again.planes.size() != samples.size()) return false;
    for (std::size_t k = 0; k < again.planes.size(); ++k) {
      const CodedPlane& plane = again.planes[k];
      const mpeg4::FbaSample& sample = samples[k];
      const auto first = again.bytes.begin() + static_cast<std::ptrdiff_t>(plane.offset);
      if (!std::equal(first, first + static_cast<std::ptrdiff_t>(plane.size), sample.bytes.begin(),
                      sample.bytes.end()) ||
          plane.intra != sample.sync || static_cast<std::uint32_t>(plane.frames) != sample.duration)
        return false;
    }
    return true;
  };
  return reencode_matches(path, fba->decoded, true, same, bytes);
}

namespace {

VerifyResult verify_input(const std::string& path, const ConvertOptions& options) {
  auto loaded = load(path, options);
  if (!loaded) return failed(loaded.error());
  ConvertOptions checked = options;
  checked.verify = true;
  auto encoded = encode_checked(*loaded, checked, path);
  if (!encoded) return failed(encoded.error(), loaded->warnings);
  const double bits =
      loaded->frames.frames.empty()
          ? 0.0
          : 8.0 * static_cast<double>(encoded->bytes.size()) /
                static_cast<double>(loaded->frames.frames.back().number - loaded->frames.frames.front().number + 1);
  VerifyResult result =
      passed(loaded->frames.frames.size(), encoded->bytes.size(), bits, options.quant, loaded->warnings);
  result.max_error = max_error(loaded->frames, *encoded);
  return result;
}

}  // namespace

VerifyResult verify(const std::string& path, const ConvertOptions& options) {
  // An FBA stream re-encodes to the same bytes; any other input encodes, then is checked.
  const InputFormat* format = reader_for(path, options);
  if (format && format->verify_stream) return format->verify_stream(path, options.limits);
  return verify_input(path, options);
}

}  // namespace fapc::pipeline
