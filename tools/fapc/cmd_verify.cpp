// fapc verify FILE... [--quant Q] [--intra-period N] [--ranges fit|max] [--masks fit|keep] [--json]
// A .fba stream: it decodes, and encoding its frames again with the settings it shows gives the
// same bytes (true of every stream fapc writes). An .mp4: the same for its FBA track, sample by
// sample, durations and sync flags included. Any other input: it encodes with the given
// settings, the stream decodes to within half a quantiser step of it (exactly at quant 0), and
// re-encodes to the same bytes. Exit 3 when a check fails, 1 when an input cannot be read.
#include <algorithm>
#include <functional>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "fapc/codec/file_io.hpp"
#include "fapc/convert.hpp"
#include "fapc/fba_cli.hpp"
#include "fapc/report.hpp"

namespace fapc::cli {

namespace {

struct Outcome {
  int status = kExitOk;
  std::string message;  // what was checked, or why it failed
};

std::string summary(std::size_t frames, std::size_t bytes, double bits_per_frame, int quant) {
  std::ostringstream out;
  out << frames << " frames, " << bytes << " bytes, " << std::fixed << std::setprecision(1) << bits_per_frame
      << " bits/frame at fap_quant " << quant;
  return out.str();
}

Outcome failed(const Diagnostic& d, int status) {
  report(d);
  return {status, format_diagnostic(d)};
}

// Plane distances between intra planes that no mask change explains: candidates for the period.
std::vector<int> intra_periods(const FapSequence& frames, const FbaStreamInfo& info) {
  std::vector<int> periods{0};
  std::size_t previous = 0;
  for (const FbaIntraPlane& intra : info.intra_planes) {
    const auto it = std::find_if(frames.frames.begin(), frames.frames.end(),
                                 [&](const FapFrame& f) { return f.number == intra.frame; });
    const auto k = static_cast<std::size_t>(it - frames.frames.begin());
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
Outcome reencode_matches(const std::string& path, const DecodedFba& decoded, bool aligned,
                         const std::function<bool(const EncodedFba&)>& same, std::size_t bytes) {
  const FbaStreamInfo& info = decoded.info;
  const auto failure = [&](const std::string& why) {
    return failed(make_error(Location{path, 0, 0, -1}, "verification failed: " + why), kExitVerifyFailed);
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
            return {kExitOk, summary(decoded.sequence.frames.size(), bytes, info.bits_per_frame(), options.quant)};
        }
  return failure("re-encoding the decoded frames does not give the same bytes (a stream fapc did not write?)");
}

Outcome verify_stream(const std::string& path, const Limits& limits) {
  auto raw = read_file_bytes(path, limits);
  if (!raw) return failed(raw.error(), kExitBadInput);
  const std::vector<std::uint8_t> bytes(raw->begin(), raw->end());
  FbaDecodeOptions decode_options;
  decode_options.file = path;
  decode_options.max_frames = limits.max_frames;
  auto decoded = decode_fba(bytes, decode_options);
  if (!decoded) return failed(decoded.error(), kExitBadInput);
  report_all(decoded->warnings);
  const FbaStreamInfo& info = decoded->info;
  const bool aligned = info.planes > 0 && info.plane_start_codes == info.planes;
  return reencode_matches(path, *decoded, aligned, [&](const EncodedFba& again) { return again.bytes == bytes; },
                          bytes.size());
}

// An MP4's FBA track: each sample must be the plane fapc writes for its frame, with its duration
// and sync flag.
Outcome verify_mp4(const std::string& path, const Limits& limits) {
  auto fba = read_mp4_fba(path, limits);
  if (!fba) return failed(fba.error(), kExitBadInput);
  report_all(fba->decoded.warnings);
  const std::vector<xmt::FbaSample>& samples = fba->track.samples;
  std::size_t bytes = 0;
  for (const xmt::FbaSample& sample : samples) bytes += sample.bytes.size();
  const auto same = [&](const EncodedFba& again) {
    if (again.planes.size() != samples.size()) return false;
    for (std::size_t k = 0; k < again.planes.size(); ++k) {
      const CodedPlane& plane = again.planes[k];
      const xmt::FbaSample& sample = samples[k];
      const auto first = again.bytes.begin() + static_cast<std::ptrdiff_t>(plane.offset);
      if (!std::equal(first, first + static_cast<std::ptrdiff_t>(plane.size), sample.bytes.begin(), sample.bytes.end()) ||
          plane.intra != sample.sync || static_cast<std::uint32_t>(plane.frames) != sample.duration)
        return false;
    }
    return true;
  };
  return reencode_matches(path, fba->decoded, true, same, bytes);
}

Outcome verify_input(const std::string& path, const ConvertOptions& options) {
  auto loaded = load_input(path, options);
  if (!loaded) return failed(loaded.error(), kExitBadInput);
  report_all(loaded->warnings);
  ConvertOptions checked = options;
  checked.verify = true;
  auto encoded = encode_checked(loaded->frames, checked, path);
  if (!encoded) {
    const bool verification = encoded.error().message.rfind("verification failed", 0) == 0;
    return failed(encoded.error(), verification ? kExitVerifyFailed : kExitBadInput);
  }
  const double bits = loaded->frames.frames.empty()
                          ? 0.0
                          : 8.0 * static_cast<double>(encoded->bytes.size()) /
                                static_cast<double>(loaded->frames.frames.back().number - loaded->frames.frames.front().number + 1);
  return {kExitOk, summary(loaded->frames.frames.size(), encoded->bytes.size(), bits, options.quant)};
}

int run_verify(const std::vector<std::string>& argv) {
  Args args(argv, with_limits({"quant", "intra-period", "ranges", "masks"}), {"json"});
  const ConvertOptions options = convert_options(args);
  if (!args.ok()) return usage_error("verify", args.error());
  if (args.positionals().empty()) return usage_error("verify", "expected at least one FILE");
  int status = kExitOk;
  nlohmann::ordered_json results = nlohmann::ordered_json::array();
  for (const std::string& path : args.positionals()) {
    const InputFormat* format = input_format_for(path);
    const std::string kind = format ? format->kind : "";
    const Outcome outcome = kind == "fba"   ? verify_stream(path, options.limits)
                            : kind == "mp4" ? verify_mp4(path, options.limits)
                                            : verify_input(path, options);
    if (outcome.status == kExitBadInput || (outcome.status == kExitVerifyFailed && status == kExitOk))
      status = outcome.status;
    if (args.flag("json")) {
      results.push_back({{"file", path}, {"ok", outcome.status == kExitOk}, {"status", outcome.status},
                         {"message", outcome.message}});
    } else if (outcome.status == kExitOk) {
      std::cout << path << ": ok: " << outcome.message << '\n';
    }
  }
  if (args.flag("json")) std::cout << results.dump(2) << '\n';
  return status;
}

const RegisterCommand verify_command{
    "verify", "fapc verify FILE... [--quant Q] [--intra-period N] [--ranges fit|max] [--masks fit|keep] [--json]", run_verify};

}  // namespace

}  // namespace fapc::cli
