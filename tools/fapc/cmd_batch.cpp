// fapc batch INPUT... -o DIR [--to LIST] [--jobs N] [--report junit.xml] [--report-json FILE] [--keep-going]
//            [--files-from LIST] [--shard I/N | --shards N] [--force]:
// converts every supported file under the inputs into DIR (fapc::pipeline::plan_batch and
// run_batch), one output per kind in --to, and prints a summary line per input, in input order,
// as the jobs finish. Ctrl-C stops starting new jobs; the summary and the report still come.
// On a cluster (docs/cluster.md) each node plans the same batch and converts its shard; jobs a
// completion record says are finished are skipped, so a killed task is simply run again.
#include <algorithm>
#include <atomic>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>
#include <string_view>

#include "fapc/cli_codes.hpp"
#include "fapc/cli_spec.hpp"
#include "fapc/codec/file_io.hpp"
#include "fapc/commands.hpp"
#include "fapc/help.hpp"
#include "fapc/options.hpp"
#include "fapc/pipeline/batch.hpp"
#include "fapc/pipeline/batch_resume.hpp"
#include "fapc/pipeline/batch_shard.hpp"
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

// The paths of a --files-from list, one a line ("-": standard input); blank lines are skipped.
Result<std::vector<std::string>> read_list(const std::string& list) {
  std::ifstream file;
  if (list != "-") {
    file.open(list, std::ios::binary);
    if (!file)
      return make_error(codes::cli::files_from_unreadable, Location::whole_file(list),
                        "cannot open the --files-from list");
  }
  std::istream& in = list == "-" ? std::cin : file;
  std::vector<std::string> paths;
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (!line.empty()) paths.push_back(line);
  }
  return paths;
}

// The options that change no output's bytes: a re-run that differs only in these resumes.
const std::set<std::string_view> kRunOnlyOptions = {"jobs",  "report",  "report-json", "keep-going",
                                                    "shard", "shards",  "files-from",  "force",
                                                    "quiet", "verbose", "output",      "help"};

// The options of a command line that decide the outputs' bytes, as one line in a fixed order
// ("--fps=30 --points"), whatever order and spelling (-oX, --opt X, --opt=X) they were given in:
// what a completion record compares. The line was parsed by Args already, so every option is known.
std::string output_settings(const std::vector<std::string>& argv) {
  std::vector<std::pair<std::string_view, std::string>> given;  // (option, "--option=value")
  for (std::size_t i = 0; i < argv.size(); ++i) {
    const std::string& arg = argv[i];
    if (arg == "--") break;
    if (arg.size() < 2 || arg[0] != '-') continue;
    const bool long_form = arg[1] == '-';
    const std::string name = long_form ? arg.substr(2, arg.find('=') - 2) : arg.substr(1, 1);
    const OptionSpec* option = long_form ? find_option(name) : find_short_option(name[0]);
    if (!option) continue;
    std::string value;
    if (option->takes_value()) {
      if (long_form && arg.find('=') != std::string::npos)
        value = arg.substr(arg.find('=') + 1);
      else if (!long_form && arg.size() > 2)
        value = arg.substr(2);
      else if (i + 1 < argv.size())
        value = argv[++i];
    }
    if (!kRunOnlyOptions.count(option->name))
      given.emplace_back(option->name, "--" + std::string(option->name) + "=" + value);
  }
  // By option; a repeated option's values keep their order (two --event in turn may differ).
  std::stable_sort(given.begin(), given.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::string line;
  for (const auto& [name, setting] : given) line += (line.empty() ? "" : " ") + setting;
  return line;
}

// The shard this process converts: --shard, else the scheduler's environment, else none.
Result<std::optional<pipeline::Shard>> chosen_shard(Args& args) {
  if (const auto given = args.value("shard")) {
    auto shard = pipeline::parse_shard(*given);
    if (!shard) return shard.error();
    return std::optional<pipeline::Shard>{*shard};
  }
  std::optional<std::size_t> shards;
  if (args.value("shards")) shards = static_cast<std::size_t>(args.integer("shards", 1));
  if (!args.ok()) return make_error(codes::cli::bad_option, Location{}, args.error());
  return pipeline::shard_from_environment([](const char* name) { return std::getenv(name); }, shards);
}

// A report's folder is made if missing: the first report is written before any output (and
// before the outputs' folders), and `--report-json out/report.json` is a usual way to ask for it.
Status write_report(const std::optional<std::string>& path, const std::string& text) {
  if (!path) return ok_status();
  std::error_code ec;
  if (const auto folder = std::filesystem::path(*path).parent_path(); !folder.empty())
    std::filesystem::create_directories(folder, ec);  // a failure is the write's to report
  return write_file_atomic(*path, text);
}

int run_batch(const std::vector<std::string>& argv) {
  Args args("batch", argv);
  ConvertOptions options = convert_options(args);
  // A batch's inputs are of many kinds: an option is for those that read it, and the others are
  // not warned of it (docs/cli.md, "Options a kind does not read").
  options.given.clear();
  const int threads = args.integer("jobs", 0);  // absent: one per core
  if (!args.ok()) return usage_error("batch", args);
  const auto out_dir = args.value("output");
  if (!out_dir) return usage_error("batch", codes::cli::missing_output, "missing -o DIR");
  std::vector<std::string> inputs = args.positionals();
  std::optional<std::vector<std::string>> listed;
  if (const auto list = args.value("files-from")) {
    auto paths = read_list(*list);
    if (!paths) return report_outcome({}, paths.error());
    listed = std::move(*paths);
    if (inputs.empty()) inputs.push_back(".");
  }
  // The reports' paths are refused before any job runs when they cannot take a report.
  for (const char* report : {"report", "report-json"})
    if (const auto path = args.value(report))
      if (auto writable = check_output_path(*path); !writable) return report_outcome({}, writable.error());
  if (inputs.empty()) return usage_error("batch", codes::cli::operands, "expected at least one INPUT");
  auto shard = chosen_shard(args);
  if (!shard) return usage_error("batch", shard.error());
  auto planned =
      pipeline::plan_batch(inputs, *out_dir, split_list(args.value("to").value_or("fap")), listed ? &*listed : nullptr);
  if (!planned) {
    // A usage error about a named path is reported as a diagnostic on that path.
    if (planned.error().where.file.empty()) return usage_error("batch", planned.error());
    return report_outcome({}, planned.error());
  }
  const std::vector<pipeline::BatchJob> jobs = *shard ? pipeline::select_shard(*planned, **shard) : *planned;
  if (*shard)
    tell("shard " + std::to_string((*shard)->index) + "/" + std::to_string((*shard)->count) + ": " +
         std::to_string(jobs.size()) + " of " + std::to_string(planned->size()) + " jobs");
  // A folder given to batch is the inputs' tree: their includes may read anywhere in it.
  for (const std::string& input : inputs)
    if (std::filesystem::is_directory(input)) options.includes.allowed_folders.push_back(input);

  const auto json_report = [&](const std::vector<pipeline::BatchOutcome>& outcomes) {
    return pipeline::batch_report_json(jobs, outcomes, interrupted, *shard, planned->size()).dump(2) + "\n";
  };
  // Written first with every job not run, so that a task killed before its end still names its
  // jobs to `fapc batch-report merge`; replaced at the end.
  if (auto written =
          write_report(args.value("report-json"), json_report(std::vector<pipeline::BatchOutcome>(jobs.size())));
      !written)
    return report_outcome({}, written.error());

  const pipeline::CompletionRecords records(*out_dir, output_settings(argv) + " (" + version_text() + ")", jobs);
  pipeline::BatchRunOptions run;
  run.threads = threads;
  run.keep_going = args.flag("keep-going");
  run.stop = &interrupted;
  run.records = &records;
  run.redo_all = args.flag("force");
  // Each job's diagnostics and summary are printed together, in input order.
  ProgressBar bar(progress_wanted());
  run.in_order = [&](std::size_t index, const pipeline::BatchOutcome& outcome) {
    report_outcome(outcome.result.warnings, outcome.result.error);
    std::cout << pipeline::batch_summary_line(jobs[index], outcome) << '\n' << std::flush;
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%.3f s", outcome.seconds);
    tell(jobs[index].input + ": " + seconds);
  };
  if (bar.enabled())
    run.progress = [&bar](std::size_t finished, std::size_t total) {
      bar.update("inputs", static_cast<std::int64_t>(finished), static_cast<std::int64_t>(total));
    };
  struct sigaction action {};
  action.sa_handler = on_interrupt;
  struct sigaction old_int {
  }, old_term{};
  ::sigaction(SIGINT, &action, &old_int);
  ::sigaction(SIGTERM, &action, &old_term);
  const std::vector<pipeline::BatchOutcome> outcomes = pipeline::run_batch(jobs, options, run);
  ::sigaction(SIGINT, &old_int, nullptr);
  ::sigaction(SIGTERM, &old_term, nullptr);

  std::size_t failed = 0, converted = 0, up_to_date = 0;
  int status = kExitOk;
  for (const pipeline::BatchOutcome& o : outcomes) {
    up_to_date += o.up_to_date;
    if (!o.ran) continue;
    if (o.result.ok()) {
      ++converted;
    } else {
      ++failed;
      status = worse_status(status, exit_status(o.result.error->kind));
    }
  }
  // A report's folder is made when missing: the output folder holding it is removed at the end
  // of a batch whose every job failed (it was made for outputs none of which were written).
  for (const char* report : {"report", "report-json"})
    if (const auto path = args.value(report))
      if (const auto folder = std::filesystem::path(*path).parent_path(); !folder.empty()) {
        std::error_code ignored;  // a folder that cannot be made fails the report's write, which says why
        std::filesystem::create_directories(folder, ignored);
      }
  std::cout << converted << " converted, " << failed << " failed, " << outcomes.size() - converted - failed - up_to_date
            << " not run";
  if (up_to_date) std::cout << ", " << up_to_date << " up to date";
  std::cout << (interrupted ? " (interrupted)" : "") << '\n';
  if (auto written = write_report(args.value("report"), pipeline::junit_report(jobs, outcomes)); !written)
    status = worse_status(status, report_outcome({}, written.error()));
  if (auto written = write_report(args.value("report-json"), json_report(outcomes)); !written)
    status = worse_status(status, report_outcome({}, written.error()));
  if (interrupted && status == kExitOk) status = kExitBadInput;  // not everything was converted
  return status;
}

const RegisterCommand batch_command{"batch", run_batch};

}  // namespace

}  // namespace fapc::cli
