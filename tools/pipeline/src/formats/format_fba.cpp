// .fba raw MPEG-4 FBA streams, in and out; `fapc info` gets the stream's statistics. Streamed, a
// .fba is decoded from its mapping frame by frame, and written by the encoder fed so.
#include <filesystem>

#include "../fba_frame_writer.hpp"
#include "../verify_streams.hpp"
#include "fapc/pipeline/codes.hpp"
#include "fapc/pipeline/fba_io.hpp"
#include "fapc/pipeline/json_access.hpp"
#include "fapc/pipeline/registry.hpp"

namespace fapc::pipeline::builtin {

namespace {

nlohmann::ordered_json facts_of(const FbaStreamInfo& info) {
  nlohmann::ordered_json out;
  out["stream_bytes"] = info.bytes;
  if (info.profile_and_level >= 0) out["profile_and_level"] = info.profile_and_level;
  out["planes"] = info.planes;
  out["intra_planes"] = info.intra_planes.size();
  std::vector<std::int64_t> intra_frames;
  std::vector<int> quants;
  for (const FbaIntraPlane& intra : info.intra_planes) {
    intra_frames.push_back(intra.frame);
    if (quants.empty() || quants.back() != intra.fap_quant) quants.push_back(intra.fap_quant);
  }
  out["intra_frames"] = intra_frames;
  out["fap_quant"] = quants;
  out["frames_covered"] = info.frames;
  out["skipped_frames"] = info.skipped_frames;
  out["bits_per_frame"] = info.bits_per_frame();
  out["frame_rate"] = info.frame_rate;
  out["plane_start_codes"] = info.plane_start_codes;
  if (info.body_planes > 0) out["body_planes_ignored"] = info.body_planes;
  // The widest ranges signalled, in quantised units: intra, then predictive.
  nlohmann::ordered_json ranges = nlohmann::ordered_json::array();
  for (int fap = 3; fap <= kFapCount; ++fap) {
    const auto i = static_cast<std::size_t>(fap - 1);
    if (!info.ranged[i]) continue;
    ranges.push_back({{"fap", fap},
                      {"name", fap_table()[i].name},
                      {"intra_min", info.intra_range[i].min},
                      {"intra_max", info.intra_range[i].max},
                      {"predictive_min", info.pred_range[i].min},
                      {"predictive_max", info.pred_range[i].max}});
  }
  out["quantised_ranges"] = ranges;
  return out;
}

Result<Loaded> load_fba(const std::string& path, const ConvertOptions& options) {
  auto decoded = read_fba_file(path, options.limits);
  if (!decoded) return decoded.error();
  Loaded loaded;
  loaded.frames = std::move(decoded->sequence);
  loaded.frames.name = std::filesystem::path(path).stem().string();
  loaded.warnings = std::move(decoded->warnings);
  if (options.facts) loaded.facts = json_value(facts_of(decoded->info));
  return loaded;
}

Result<std::string> write_fba(const Loaded& loaded, const std::string& path, const ConvertOptions& options) {
  auto encoded = encode_checked(loaded, options, loaded.named(path));
  if (!encoded) return encoded.error();
  return std::string(encoded->bytes.begin(), encoded->bytes.end());
}

// A .fba decoded twice, or once onto the tape: its frames have their numbers as soon as decoded.
class FbaSource : public FrameSource {
 public:
  FbaSource(MappedFile file, const std::string& path, const ConvertOptions& options) : file_(std::move(file)) {
    options_.file = path;
    options_.max_frames = options.limits.max_frames;
    name_ = std::filesystem::path(path).stem().string();
  }

  bool placed_in_first_pass() const override { return true; }

 protected:
  Result<SourceFacts> read(const FapFrameSink& check) override {
    SourceFacts facts;
    auto decoded = decode_fba(bytes(), options_, [&](const FapFrame& frame) {
      if (facts.frames++ == 0) facts.first_number = frame.number;
      facts.last_number = frame.number;
      return check(frame);
    });
    if (!decoded) return decoded.error();
    facts.name = name_;
    facts.fps = decoded->sequence.fps;
    facts.warnings = std::move(decoded->warnings);
    frames_ = facts.frames;
    return facts;
  }

  Status read_again(const FapFrameSink& code) override {
    std::size_t k = 0;
    auto again = decode_fba(bytes(), options_, [&](const FapFrame& frame) {
      ++k;
      return code(frame);
    });
    if (!again || k != frames_)
      return make_error(codes::input::changed_while_read, Location::whole_file(options_.file),
                        "the file changed while it was read");
    return ok_status();
  }
  std::size_t frames_read() const override { return frames_; }

 private:
  std::span<const std::uint8_t> bytes() const {
    return {reinterpret_cast<const std::uint8_t*>(file_.bytes().data()), file_.bytes().size()};
  }
  MappedFile file_;
  FbaDecodeOptions options_;
  std::string name_;
  std::size_t frames_ = 0;
};

}  // namespace

InputFormat fba_input() {
  InputFormat format{"fba", {".fba", ".fba.gz"}, load_fba};
  format.frames = [](MappedFile file, const std::string& path, const ConvertOptions& options) {
    return std::unique_ptr<FrameSource>(std::make_unique<FbaSource>(std::move(file), path, options));
  };
  format.verify_stream = verify_fba_file;
  return format;
}

OutputFormat fba_output() {
  OutputFormat format{"fba", {".fba"}, write_fba};
  format.frame_writer = [](const std::string& path, const std::string& input, const ConvertOptions& options,
                           FrameSource& source) {
    return std::unique_ptr<FrameWriter>(std::make_unique<FbaFrameWriter>(path, input, options, source, false));
  };
  return format;
}

}  // namespace fapc::pipeline::builtin
