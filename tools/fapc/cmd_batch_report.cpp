// fapc batch-report merge REPORT.json... [--report-json FILE] [--report junit.xml]: the JSON reports
// of a sharded batch's tasks as one (fapc::pipeline::merge_batch_reports); prints the jobs and
// shards with no result and the counts. Exit status 0 only when every planned job converted (now
// or, up to date, earlier): a script may resubmit the array while it is not.
#include <iostream>

#include "fapc/codec/file_io.hpp"
#include "fapc/commands.hpp"
#include "fapc/options.hpp"
#include "fapc/pipeline/batch_merge.hpp"
#include "fapc/pipeline/json_access.hpp"
#include "fapc/report.hpp"

namespace fapc::cli {

namespace {

int run_batch_report(const std::vector<std::string>& argv) {
  Args args("batch-report", argv);
  if (!args.ok()) return usage_error("batch-report", args);
  const std::vector<std::string>& operands = args.positionals();
  if (operands.empty() || operands.front() != "merge")
    return usage_error("batch-report", codes::cli::operands, "expected merge REPORT.json... (the one action so far)");
  if (operands.size() < 2)
    return usage_error("batch-report", codes::cli::operands, "expected at least one REPORT.json to merge");
  std::vector<pipeline::ReportText> reports;
  for (std::size_t i = 1; i < operands.size(); ++i) {
    auto text = read_file_bytes(operands[i]);
    if (!text) return report_outcome({}, text.error());
    reports.push_back({operands[i], std::move(*text)});
  }
  auto merged = pipeline::merge_batch_reports(reports);
  if (!merged) return report_outcome({}, merged.error());
  const auto& totals = json_of(merged->report)["totals"];
  for (const std::string& input : merged->failed) std::cout << "FAILED " << input << '\n';
  for (const std::string& input : merged->no_result) std::cout << "no result: " << input << '\n';
  for (const std::size_t index : merged->missing_shards)
    std::cout << "no report: shard " << index << "/" << json_of(merged->report)["merged"]["shards"].get<std::size_t>()
              << '\n';
  std::cout << reports.size() << " reports, " << totals["jobs"].get<std::size_t>()
            << " jobs planned: " << totals["converted"].get<std::size_t>() << " converted, "
            << totals["up_to_date"].get<std::size_t>() << " up to date, " << totals["failed"].get<std::size_t>()
            << " failed, " << totals["not_run"].get<std::size_t>() << " with no result\n";
  int status = merged->complete() ? kExitOk : kExitBadInput;
  if (const auto path = args.value("report-json"))
    if (auto written = write_file_atomic(*path, merged->report.dump(2) + "\n"); !written)
      status = worse_status(status, report_outcome({}, written.error()));
  if (const auto path = args.value("report"))
    if (auto written = write_file_atomic(*path, pipeline::junit_from_report(merged->report)); !written)
      status = worse_status(status, report_outcome({}, written.error()));
  return status;
}

const RegisterCommand batch_report_command{"batch-report", run_batch_report};

}  // namespace

}  // namespace fapc::cli
