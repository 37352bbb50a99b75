// Merging the reports of a sharded batch (`fapc batch-report merge`, docs/cluster.md): each shard
// writes the JSON report of its own jobs (at its start with every job not run, then at its end),
// and the merge says what became of every planned job, and which jobs or shards have no result.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "fapc/codec/diagnostic.hpp"

namespace fapc::pipeline {

struct ReportText {
  std::string path;  // for errors
  std::string text;  // a `batch --report-json` document
};

struct MergedReport {
  // The batch report's shape (docs/json.md) with "shard": null and a "merged" object.
  nlohmann::ordered_json report;
  std::vector<std::string> failed;          // inputs whose best result is a failure
  std::vector<std::string> no_result;       // inputs planned, in a report, but never converted
  std::vector<std::size_t> missing_shards;  // shard indexes with no report: their jobs are unknown
  std::size_t unnamed_without_result = 0;   // planned jobs in no report at all (missing shards)
  bool complete() const {
    return failed.empty() && no_result.empty() && missing_shards.empty() && !unnamed_without_result;
  }
};

// Errors: a report that is not JSON (bad_input, at its byte), not a batch report, or reports of
// different batches (other shard counts or other planned totals: usage). A job in several reports
// (a shard run twice) takes its best result: converted or up to date, then failed, then not run.
Result<MergedReport> merge_batch_reports(const std::vector<ReportText>& reports);

// A JUnit XML report of a batch report (one shard's or a merged one): a test case per job that
// converted, was up to date or failed; in a merged report also an error per planned job and per
// shard with no result, so that missing work is red on a dashboard.
std::string junit_from_report(const nlohmann::ordered_json& report);

}  // namespace fapc::pipeline
