// .fba raw MPEG-4 FBA streams, in and out; `fapc info` gets the stream's statistics.
#include <filesystem>

#include "fapc/pipeline/fba_io.hpp"
#include "formats.hpp"

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
    ranges.push_back({{"fap", fap}, {"name", fap_table()[i].name}, {"intra_min", info.intra_range[i].min},
                      {"intra_max", info.intra_range[i].max}, {"predictive_min", info.pred_range[i].min},
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
  if (options.facts) loaded.facts = facts_of(decoded->info);
  return loaded;
}

Result<std::string> write_fba(const Loaded& loaded, const std::string& path, const ConvertOptions& options) {
  auto encoded = encode_checked(loaded.frames, options, loaded.named(path));
  if (!encoded) return encoded.error();
  return std::string(encoded->bytes.begin(), encoded->bytes.end());
}

}  // namespace

InputFormat fba_input() { return {"fba", {".fba", ".fba.gz"}, load_fba}; }
OutputFormat fba_output() { return {"fba", {".fba"}, write_fba}; }

}  // namespace fapc::pipeline::builtin
