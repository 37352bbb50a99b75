#include "fapc/pipeline/json_output.hpp"

#include <bitset>

namespace fapc::pipeline {

using json = nlohmann::ordered_json;

json diagnostic_json(const Diagnostic& d) {
  const bool error = d.severity == Severity::error;
  return {{"severity", error ? "error" : "warning"},
          {"kind", error ? json(error_kind_name(d.kind)) : json(nullptr)},
          {"code", d.code.empty() ? json(nullptr) : json(d.code)},
          {"file", d.where.file},
          {"line", d.where.line > 0 ? json(d.where.line) : json(nullptr)},
          {"column", d.where.line > 0 && d.where.column > 0 ? json(d.where.column) : json(nullptr)},
          {"byte", d.where.byte_offset >= 0 ? json(d.where.byte_offset) : json(nullptr)},
          {"message", d.message},
          {"text", format_diagnostic(d)}};
}

json diagnostics_json(const Diagnostics& ds) {
  json out = json::array();
  for (const Diagnostic& d : ds) out.push_back(diagnostic_json(d));
  return out;
}

json error_document(const Diagnostic& d) {
  return {{"schema_version", kJsonSchemaVersion}, {"error", diagnostic_json(d)}};
}

json verify_file_json(const std::string& path, const VerifyResult& result, int exit_status) {
  json out;
  out["file"] = path;
  out["ok"] = result.ok();
  out["exit_status"] = exit_status;
  if (result.ok()) {
    out["frames"] = result.frames;
    out["bytes"] = result.bytes;
    out["bits_per_frame"] = result.bits_per_frame;
    out["fap_quant"] = result.quant;
    out["max_error"] = result.max_error ? json(*result.max_error) : json(nullptr);
    out["summary"] = result.summary;
  }
  out["error"] = result.error ? diagnostic_json(*result.error) : json(nullptr);
  out["warnings"] = diagnostics_json(result.warnings);
  return out;
}

json verify_document(std::vector<json> files) {
  json out;
  out["schema_version"] = kJsonSchemaVersion;
  out["files"] = json::array();
  for (json& file : files) out["files"].push_back(std::move(file));
  return out;
}

json batch_report_json(const std::vector<BatchJob>& jobs, const std::vector<BatchOutcome>& outcomes, bool interrupted,
                       const std::optional<Shard>& shard, std::size_t planned) {
  json list = json::array();
  std::size_t ran = 0, failed = 0, up_to_date = 0;
  double seconds = 0;
  for (std::size_t i = 0; i < jobs.size() && i < outcomes.size(); ++i) {
    const BatchOutcome& o = outcomes[i];
    json job;
    job["input"] = jobs[i].input;
    job["ran"] = o.ran;
    job["up_to_date"] = o.up_to_date;
    job["ok"] = (o.ran && o.result.ok()) || o.up_to_date;
    job["seconds"] = o.seconds;
    json outputs = json::array();
    for (const OutputRequest& request : jobs[i].outputs) outputs.push_back(request.path);
    job["outputs"] = outputs;
    job["written"] = o.up_to_date ? json::array() : json(o.result.written);
    if (o.ran && o.result.ok()) {
      // result.frames, not result.loaded: streamed conversions and curve outputs hold no frames.
      const FramesSeen& seen = o.result.frames;
      job["frames"] = seen.count;
      job["fps"] = seen.fps;
      job["duration"] = seen.duration_seconds();
      job["faps_used"] = seen.faps.count();
    }
    job["error"] = o.result.error ? diagnostic_json(*o.result.error) : json(nullptr);
    job["warnings"] = diagnostics_json(o.result.warnings);
    ran += o.ran;
    failed += o.ran && !o.result.ok();
    up_to_date += o.up_to_date;
    seconds += o.seconds;
    list.push_back(std::move(job));
  }
  json out;
  out["schema_version"] = kJsonSchemaVersion;
  out["shard"] = shard ? json{{"index", shard->index}, {"count", shard->count}} : json(nullptr);
  out["planned"] = shard ? planned : jobs.size();
  out["jobs"] = std::move(list);
  out["totals"] = {{"jobs", jobs.size()},
                   {"converted", ran - failed},
                   {"up_to_date", up_to_date},
                   {"failed", failed},
                   {"not_run", jobs.size() - ran - up_to_date},
                   {"interrupted", interrupted},
                   {"job_seconds", seconds}};
  return out;
}

}  // namespace fapc::pipeline
