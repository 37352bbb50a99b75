// fapc batch INPUT... -o DIR [--to LIST] [--jobs N] [--report junit.xml] [--keep-going]:
// converts every supported file under the inputs into DIR, one output per kind in --to, and
// prints a summary line per input.
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <mutex>
#include <sstream>
#include <thread>

#include "fapc/xml_text.hpp"
#include "fapc/codec/file_io.hpp"
#include "fapc/convert.hpp"

namespace fapc::cli {

namespace {

namespace fs = std::filesystem;

struct Job {
  std::string input;
  std::string relative;  // path under its input folder, without the input extension
};

struct JobResult {
  int status = kExitOk;
  std::string summary;
  double seconds = 0;
};

std::string strip_input_extension(const std::string& path) {
  const InputFormat* format = input_format_for(path);
  for (const std::string& ext : format->extensions)
    if (path.size() > ext.size() && path.compare(path.size() - ext.size(), ext.size(), ext) == 0)
      return path.substr(0, path.size() - ext.size());
  return path;
}

// Files given by name are taken whatever they are (an unknown kind is then an error); folders
// contribute their supported files, in sorted order so runs are repeatable.
std::vector<Job> collect(const std::vector<std::string>& inputs) {
  std::vector<Job> jobs;
  for (const std::string& input : inputs) {
    if (!fs::is_directory(input)) {
      const bool known = input_format_for(input) != nullptr;
      jobs.push_back({input, known ? fs::path(strip_input_extension(input)).filename().string()
                                   : fs::path(input).filename().string()});
      continue;
    }
    std::vector<std::string> found;
    for (const auto& entry : fs::recursive_directory_iterator(input))
      if (entry.is_regular_file() && input_format_for(entry.path().string()))
        found.push_back(entry.path().string());
    std::sort(found.begin(), found.end());
    for (const std::string& path : found)
      jobs.push_back({path, fs::relative(strip_input_extension(path), input).string()});
  }
  return jobs;
}

std::vector<std::string> split_list(const std::string& list) {
  std::vector<std::string> out;
  std::stringstream s(list);
  for (std::string item; std::getline(s, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}


std::string junit_report(const std::vector<Job>& jobs, const std::vector<JobResult>& results) {
  std::size_t failures = 0;
  for (const JobResult& r : results) failures += r.status != kExitOk;
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuite name=\"fapc batch\" tests=\"" +
                    std::to_string(jobs.size()) + "\" failures=\"" + std::to_string(failures) + "\">\n";
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    out += "  <testcase name=\"" + xml_escape(jobs[i].input) + "\" time=\"" +
           std::to_string(results[i].seconds) + "\"";
    if (results[i].status == kExitOk) {
      out += "/>\n";
    } else {
      out += "><failure message=\"exit status " + std::to_string(results[i].status) + "\">" +
             xml_escape(results[i].summary) + "</failure></testcase>\n";
    }
  }
  return out + "</testsuite>\n";
}

int run_batch(const std::vector<std::string>& argv) {
  Args args(argv, [] { auto v = kConvertValued; v.insert({"output", "jobs", "report"}); return v; }(),
            [] { auto f = kConvertFlags; f.insert("keep-going"); return f; }());
  ConvertOptions options = convert_options(args);
  const int jobs_wanted = args.integer("jobs", 1, 1, 256);
  if (!args.ok()) return usage_error("batch", args.error());
  const auto out_dir = args.value("output");
  if (!out_dir) return usage_error("batch", "missing -o DIR");
  if (args.positionals().empty()) return usage_error("batch", "expected at least one INPUT");
  const std::vector<std::string> kinds = split_list(args.value("to").value_or("fap"));
  for (const std::string& kind : kinds)
    if (!output_format_named(kind)) return usage_error("batch", "unknown output kind '" + kind + "'");
  for (const std::string& input : args.positionals())
    if (!fs::exists(input)) return usage_error("batch", "no such file or folder: " + input);
  // A folder given to batch is the inputs' tree: their includes may read anywhere in it.
  for (const std::string& input : args.positionals())
    if (fs::is_directory(input)) options.includes.allowed_folders.push_back(input);

  const std::vector<Job> jobs = collect(args.positionals());
  std::vector<JobResult> results(jobs.size());
  const bool keep_going = args.flag("keep-going");
  const bool progress = ::isatty(STDERR_FILENO) != 0;
  std::atomic<std::size_t> next{0}, done{0};
  std::atomic<bool> stop{false};
  std::mutex console;
  const auto worker = [&] {
    for (std::size_t i; !stop && (i = next++) < jobs.size();) {
      const auto start = std::chrono::steady_clock::now();
      JobResult& result = results[i];
      std::ostringstream summary;
      // The input is loaded (and its warnings printed) once, with the first output kind; the
      // other kinds are written from what it became.
      ConvertOutcome outcome;
      for (const std::string& kind : kinds) {
        const std::string output =
            (fs::path(*out_dir) / (jobs[i].relative + output_format_named(kind)->extensions.front()))
                .string();
        fs::create_directories(fs::path(output).parent_path());
        std::lock_guard<std::mutex> lock(console);  // diagnostics of one file stay together
        const bool first = &kind == &kinds.front();
        const int status = first ? (outcome = convert(jobs[i].input, output, options, kind)).exit_status
                                 : write_output(outcome.loaded, output, options, kind);
        if (status != kExitOk) {
          result.status = status;
          summary.str("");
          summary << "FAILED " << jobs[i].input;
          break;
        }
        if (first) {
          const FapSequence& seq = outcome.loaded.frames;
          std::size_t faps = 0;
          std::bitset<kFapCount> used;
          for (const FapFrame& f : seq.frames) used |= f.mask;
          faps = used.count();
          summary << jobs[i].input << ": " << seq.frames.size() << " frames, " << seq.fps
                  << " fps, " << faps << " FAPs, " << outcome.loaded.warnings.size()
                  << " warnings ->";
        }
        summary << ' ' << output;
      }
      result.summary = summary.str();
      result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (result.status != kExitOk && !keep_going) stop = true;
      const std::size_t finished = ++done;
      std::lock_guard<std::mutex> lock(console);
      if (progress) std::cerr << "\r[" << finished << "/" << jobs.size() << "] " << std::flush;
    }
  };
  std::vector<std::thread> threads;
  for (int t = 0; t < jobs_wanted; ++t) threads.emplace_back(worker);
  for (std::thread& t : threads) t.join();
  if (progress) std::cerr << "\r\n";

  std::size_t failed = 0, converted = 0;
  for (const JobResult& r : results) {
    if (r.summary.empty()) continue;  // not started after a failure without --keep-going
    std::cout << r.summary << '\n';
    (r.status == kExitOk ? converted : failed)++;
  }
  std::cout << converted << " converted, " << failed << " failed, "
            << jobs.size() - converted - failed << " not run\n";
  if (const auto report_path = args.value("report")) {
    if (auto written = write_file_atomic(*report_path, junit_report(jobs, results)); !written) {
      std::cerr << format_diagnostic(written.error()) << '\n';
      return kExitBadInput;
    }
  }
  if (failed == 0) return kExitOk;
  for (const JobResult& r : results)
    if (r.status == kExitVerifyFailed) return kExitVerifyFailed;
  return kExitBadInput;
}

const RegisterCommand batch_command{
    "batch",
    "fapc batch INPUT... -o DIR [--to LIST] [--jobs N] [--report junit.xml] [--keep-going]",
    run_batch};

}  // namespace

}  // namespace fapc::cli
