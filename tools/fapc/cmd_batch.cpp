// fapc batch INPUT... -o DIR [--to LIST] [--jobs N] [--report junit.xml] [--report-json FILE] [--keep-going]:
// converts every supported file under the inputs into DIR (fapc::pipeline::plan_batch and
// run_batch), one output per kind in --to, and prints a summary line per input, in input order,
// as the jobs finish. Ctrl-C stops starting new jobs; the summary and the report still come.
#include <atomic>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "fapc/codec/file_io.hpp"
#include "fapc/commands.hpp"
#include "fapc/options.hpp"
#include "fapc/pipeline/batch.hpp"
#include "fapc/pipeline/json_output.hpp"
#include "fapc/progress.hpp"
#include "fapc/report.hpp"

namespace fapc::cli {

namespace {

// Set by SIGINT/SIGTERM: running jobs finish their outputs (written whole or not at all), no new
// job starts. A lock-free atomic is what a signal handler may touch.
std::atomic<bool> interrupted{false};
static_assert(std::atomic<bool>::is_always_lock_free);

extern "C" void on_interrupt(int) { interrupted = true; }

std::vector<std::string> split_list(const std::string& list) {
  std::vector<std::string> out;
  std::stringstream s(list);
  for (std::string item; std::getline(s, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}

int run_batch(const std::vector<std::string>& argv) {
  Args args("batch", argv);
  ConvertOptions options = convert_options(args);
  const int threads = args.integer("jobs", 0, 1, 256);  // absent: one per core
  if (!args.ok()) return usage_error("batch", args.error());
  const auto out_dir = args.value("output");
  if (!out_dir) return usage_error("batch", "missing -o DIR");
  if (args.positionals().empty()) return usage_error("batch", "expected at least one INPUT");
  auto jobs = pipeline::plan_batch(args.positionals(), *out_dir, split_list(args.value("to").value_or("fap")));
  if (!jobs) {
    // A usage error about a named path is reported as a diagnostic on that path.
    if (jobs.error().where.file.empty()) return usage_error("batch", jobs.error().message);
    return report_outcome({}, jobs.error());
  }
  // The reports' paths are refused before any job runs when they cannot take a report.
  for (const char* report : {"report", "report-json"})
    if (const auto path = args.value(report))
      if (auto writable = check_output_path(*path); !writable) return report_outcome({}, writable.error());
  // A folder given to batch is the inputs' tree: their includes may read anywhere in it.
  for (const std::string& input : args.positionals())
    if (std::filesystem::is_directory(input)) options.includes.allowed_folders.push_back(input);

  pipeline::BatchRunOptions run;
  run.threads = threads;
  run.keep_going = args.flag("keep-going");
  run.stop = &interrupted;
  // Each job's diagnostics and summary are printed together, in input order.
  ProgressBar bar(progress_wanted());
  run.in_order = [&](std::size_t index, const pipeline::BatchOutcome& outcome) {
    report_outcome(outcome.result.warnings, outcome.result.error);
    std::cout << pipeline::batch_summary_line((*jobs)[index], outcome) << '\n' << std::flush;
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%.3f s", outcome.seconds);
    tell((*jobs)[index].input + ": " + seconds);
  };
  if (bar.enabled())
    run.progress = [&bar](std::size_t finished, std::size_t total) {
      bar.update("inputs", static_cast<std::int64_t>(finished), static_cast<std::int64_t>(total));
    };
  struct sigaction action {};
  action.sa_handler = on_interrupt;
  struct sigaction old_int {}, old_term {};
  ::sigaction(SIGINT, &action, &old_int);
  ::sigaction(SIGTERM, &action, &old_term);
  const std::vector<pipeline::BatchOutcome> outcomes = pipeline::run_batch(*jobs, options, run);
  ::sigaction(SIGINT, &old_int, nullptr);
  ::sigaction(SIGTERM, &old_term, nullptr);

  std::size_t failed = 0, converted = 0;
  int status = kExitOk;
  for (const pipeline::BatchOutcome& o : outcomes) {
    if (!o.ran) continue;
    if (o.result.ok()) {
      ++converted;
    } else {
      ++failed;
      status = worse_status(status, exit_status(o.result.error->kind));
    }
  }
  std::cout << converted << " converted, " << failed << " failed, " << outcomes.size() - converted - failed
            << " not run" << (interrupted ? " (interrupted)" : "") << '\n';
  // A report's folder is made when missing: the output folder holding it is removed at the end
  // of a batch whose every job failed (it was made for outputs none of which were written).
  for (const char* report : {"report", "report-json"})
    if (const auto path = args.value(report))
      if (const auto folder = std::filesystem::path(*path).parent_path(); !folder.empty()) {
        std::error_code ignored;  // a folder that cannot be made fails the report's write, which says why
        std::filesystem::create_directories(folder, ignored);
      }
  if (const auto report_path = args.value("report")) {
    if (auto written = write_file_atomic(*report_path, pipeline::junit_report(*jobs, outcomes)); !written)
      status = worse_status(status, report_outcome({}, written.error()));
  }
  if (const auto report_path = args.value("report-json")) {
    const std::string text = pipeline::batch_report_json(*jobs, outcomes, interrupted).dump(2) + "\n";
    if (auto written = write_file_atomic(*report_path, text); !written)
      status = worse_status(status, report_outcome({}, written.error()));
  }
  if (interrupted && status == kExitOk) status = kExitBadInput;  // not everything was converted
  return status;
}

const RegisterCommand batch_command{"batch", run_batch};

}  // namespace

}  // namespace fapc::cli
