#include "fapc/pipeline/info.hpp"

#include <algorithm>
#include <array>

#include "fapc/pipeline/json_output.hpp"
#include "fapc/pipeline/registry.hpp"
#include "input_chain.hpp"

namespace fapc::pipeline {

namespace {

struct Range {
  long long min = 0, max = 0, frames = 0;
};

nlohmann::ordered_json summarise(const std::string& path, const std::string& kind, const Loaded& loaded) {
  const FapSequence& seq = loaded.frames;
  std::array<Range, kFapCount + 1> ranges{};  // by FAP number (an array: this loop sees every value)
  for (const FapFrame& frame : seq.frames)
    for (int fap = 1; fap <= kFapCount; ++fap) {
      if (!frame.has(fap)) continue;
      const long long v = fap == 1 ? frame.viseme.select1 : fap == 2 ? frame.expression.select1 : frame.value(fap);
      Range& r = ranges[static_cast<std::size_t>(fap)];
      r.min = r.frames ? std::min(r.min, v) : v;
      r.max = r.frames ? std::max(r.max, v) : v;
      ++r.frames;
    }
  nlohmann::ordered_json out;
  out["schema_version"] = kJsonSchemaVersion;
  out["file"] = path;
  out["kind"] = kind;
  out["name"] = seq.name;
  out["fps"] = seq.fps;
  out["frames"] = seq.frames.size();
  out["duration"] = seq.duration_seconds();
  nlohmann::ordered_json faps = nlohmann::ordered_json::array();
  for (int fap = 1; fap <= kFapCount; ++fap) {
    const Range& r = ranges[static_cast<std::size_t>(fap)];
    if (r.frames == 0) continue;
    const FapInfo& info = *find_fap(fap);
    faps.push_back({{"number", fap},
                    {"name", info.name},
                    {"unit", fapu_name(info.unit)},
                    {"min", r.min},
                    {"max", r.max},
                    {"frames", r.frames}});
  }
  out["faps_used"] = faps.size();
  out["faps"] = faps;
  return out;
}

}  // namespace

Result<nlohmann::ordered_json> describe(const std::string& path, const Limits& limits, const std::string& kind) {
  ConvertOptions options;
  options.facts = true;  // the format's facts come from this one read
  options.limits = limits;
  options.input_kind = kind;
  const InputFormat* format = reader_for(path, options);
  if (!format) return unknown_input_kind(path, options);
  const ReadingInput reading(path, options);  // for its includes, as load() would
  auto loaded = format->load(path, reading.options());
  if (!loaded) return loaded.error();
  nlohmann::ordered_json info = summarise(path, format->kind, *loaded);
  if (!loaded->facts.empty()) info["format"] = std::move(loaded->facts);
  info["warnings"] = diagnostics_json(loaded->warnings);
  return info;
}

}  // namespace fapc::pipeline
