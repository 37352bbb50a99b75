#include "fapc/pipeline/batch_merge.hpp"

#include <algorithm>
#include <map>
#include <set>

#include "fapc/codec/xml_escape.hpp"
#include "fapc/pipeline/codes.hpp"
#include "fapc/pipeline/json_access.hpp"
#include "fapc/pipeline/json_output.hpp"

namespace fapc::pipeline {

namespace {

using json = nlohmann::ordered_json;

// How much a job's entry says: a converted or up-to-date job beats a failure, which beats not run.
int rank(const json& job) {
  if (job.value("ok", false)) return job.value("ran", false) ? 3 : 2;
  return job.value("ran", false) ? 1 : 0;
}

// The key jobs are ranked and dealt into shards by (batch_shard.hpp): the first output.
std::string job_key(const json& job) {
  const json& outputs = job["outputs"];
  return outputs.is_array() && !outputs.empty() && outputs[0].is_string() ? outputs[0].get<std::string>()
                                                                          : job["input"].get<std::string>();
}

Diagnostic not_a_report(const std::string& path, const std::string& why) {
  return make_error(codes::batch::not_a_report, Location::whole_file(path),
                    "not a fapc batch report (docs/json.md): " + why);
}

// The report's shape as far as the merge relies on it.
std::optional<std::string> shape_problem(const json& report) {
  if (!report.is_object()) return "not an object";
  if (report.value("schema_version", 0) != kJsonSchemaVersion)
    return "no schema_version " + std::to_string(kJsonSchemaVersion);
  if (!report.contains("jobs") || !report["jobs"].is_array()) return "no jobs array";
  for (const json& job : report["jobs"])
    if (!job.is_object() || !job.contains("input") || !job["input"].is_string() || !job.contains("outputs"))
      return "a job without input or outputs";
  const json& shard = report.value("shard", json());
  if (!shard.is_null() &&
      !(shard.is_object() && shard.value("count", 0u) > 0 && shard.value("index", 0u) < shard.value("count", 0u)))
    return "a shard that is not {index, count}";
  return std::nullopt;
}

}  // namespace

Result<MergedReport> merge_batch_reports(const std::vector<ReportText>& reports) {
  if (reports.empty()) return make_error(codes::batch::no_report, Location{}, "no report to merge");
  std::optional<std::size_t> shard_count, planned;
  std::set<std::size_t> shards_seen;
  std::map<std::string, json> best;  // by job key, in the order jobs are dealt
  bool interrupted = false;
  for (const ReportText& file : reports) {
    json report;
    try {
      report = json::parse(file.text);
    } catch (const json::parse_error& e) {
      return make_error(codes::batch::not_a_report, Location{file.path, 0, 0, static_cast<std::int64_t>(e.byte)},
                        "not JSON: " + std::string(e.what()));
    }
    if (const auto problem = shape_problem(report)) return not_a_report(file.path, *problem);
    const json& shard = report.value("shard", json());
    const std::size_t count = shard.is_null() ? 1 : shard["count"].get<std::size_t>();
    const std::size_t total = report.value("planned", report["jobs"].size());
    if (shard_count && *shard_count != count)
      return make_error(codes::batch::reports_disagree, Location::whole_file(file.path),
                        "a report of " + std::to_string(count) + " shards among reports of " +
                            std::to_string(*shard_count) + ": reports of different batches");
    if (planned && *planned != total)
      return make_error(codes::batch::reports_disagree, Location::whole_file(file.path),
                        "a report of a batch of " + std::to_string(total) + " jobs among reports of " +
                            std::to_string(*planned) + ": reports of different batches");
    shard_count = count;
    planned = total;
    shards_seen.insert(shard.is_null() ? 0 : shard["index"].get<std::size_t>());
    interrupted = interrupted || report.value("totals", json::object()).value("interrupted", false);
    for (const json& job : report["jobs"]) {
      auto [at, inserted] = best.try_emplace(job_key(job), job);
      if (!inserted && rank(job) > rank(at->second)) at->second = job;
    }
  }
  MergedReport merged;
  for (std::size_t i = 0; i < *shard_count; ++i)
    if (!shards_seen.count(i)) merged.missing_shards.push_back(i);
  json jobs = json::array();
  std::size_t converted = 0, up_to_date = 0, failed = 0;
  double seconds = 0;
  for (auto& [key, job] : best) {
    const int r = rank(job);
    converted += r == 3;
    up_to_date += r == 2;
    if (r == 1) {
      ++failed;
      merged.failed.push_back(job["input"].get<std::string>());
    }
    if (r == 0) merged.no_result.push_back(job["input"].get<std::string>());
    seconds += job.value("seconds", 0.0);
    jobs.push_back(std::move(job));
  }
  merged.unnamed_without_result = *planned > best.size() ? *planned - best.size() : 0;
  json& out = json_of(merged.report);
  out["schema_version"] = kJsonSchemaVersion;
  out["shard"] = nullptr;
  out["planned"] = *planned;
  out["jobs"] = std::move(jobs);
  out["totals"] = {{"jobs", *planned},
                   {"converted", converted},
                   {"up_to_date", up_to_date},
                   {"failed", failed},
                   {"not_run", *planned - converted - up_to_date - failed},
                   {"interrupted", interrupted},
                   {"job_seconds", seconds}};
  out["merged"] = {{"reports", reports.size()},
                   {"shards", *shard_count},
                   {"missing_shards", merged.missing_shards},
                   {"no_result", merged.no_result}};
  return merged;
}

std::string junit_from_report(const JsonValue& value) {
  const json& report = json_of(value);
  std::string cases;
  std::size_t tests = 0, failures = 0, errors = 0;
  const auto add_error = [&](const std::string& name, const std::string& type, const std::string& message) {
    ++tests;
    ++errors;
    cases += "  <testcase name=\"" + xml_escape(name, XmlPlace::attribute) + "\" time=\"0\"><error type=\"" + type +
             "\" message=\"" + xml_escape(message, XmlPlace::attribute) + "\"/></testcase>\n";
  };
  const bool merged = report.contains("merged");
  for (const json& job : report["jobs"]) {
    const std::string input = job["input"].get<std::string>();
    const bool ran = job.value("ran", false), up_to_date = job.value("up_to_date", false);
    if (!ran && !up_to_date) {
      if (merged) add_error(input, "no_result", "planned, but no shard converted it");
      continue;  // one shard's job stopped before it started: nothing to report
    }
    ++tests;
    cases += "  <testcase name=\"" + xml_escape(input, XmlPlace::attribute) + "\" time=\"" +
             std::to_string(job.value("seconds", 0.0)) + "\"";
    if (job.value("ok", false)) {
      cases += "/>\n";
      continue;
    }
    ++failures;
    const json& error = job.value("error", json());
    const std::string kind = error.is_object() ? error.value("kind", std::string("bad_input")) : "bad_input";
    const std::string text = error.is_object() ? error.value("text", std::string()) : std::string();
    // The error's code (docs/errors.md) after the input: what to look up, whatever the wording.
    const json code = error.is_object() ? error.value("code", json()) : json();
    const std::string shown_code = code.is_string() ? " [" + code.get<std::string>() + "]" : "";
    cases += "><failure type=\"" + kind + "\" message=\"" + xml_escape(text, XmlPlace::attribute) + "\">" +
             xml_escape("FAILED " + input + shown_code) + "</failure></testcase>\n";
  }
  if (merged) {
    const std::size_t count = report["merged"].value("shards", std::size_t{1});
    for (const json& index : report["merged"]["missing_shards"])
      add_error("shard " + std::to_string(index.get<std::size_t>()) + "/" + std::to_string(count), "no_report",
                "no report from this shard: its jobs are unknown");
  }
  const std::string errors_attribute = errors ? "\" errors=\"" + std::to_string(errors) : "";
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuite name=\"fapc batch\" tests=\"" + std::to_string(tests) +
         "\" failures=\"" + std::to_string(failures) + errors_attribute + "\">\n" + cases + "</testsuite>\n";
}

}  // namespace fapc::pipeline
