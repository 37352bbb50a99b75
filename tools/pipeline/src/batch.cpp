#include "fapc/pipeline/batch.hpp"

#include <algorithm>
#include <bitset>
#include <chrono>
#include <exception>
#include <filesystem>
#include <map>
#include <mutex>
#include <sstream>
#include <thread>

#include "fapc/pipeline/batch_merge.hpp"
#include "fapc/pipeline/batch_resume.hpp"
#include "fapc/pipeline/codes.hpp"
#include "fapc/pipeline/json_access.hpp"
#include "fapc/pipeline/json_output.hpp"
#include "fapc/speech/engine.hpp"

namespace fapc::pipeline {

namespace {

namespace fs = std::filesystem;

Diagnostic usage(ErrorCode code, const std::string& message) { return make_error(code, Location{}, message); }

std::string without_input_extension(const std::string& path) {
  if (const InputFormat* format = formats().input_for(path))
    for (const std::string& ext : format->extensions)
      if (path.size() > ext.size() && path.ends_with(ext)) return path.substr(0, path.size() - ext.size());
  return path;
}

// Whether the canonical `path` is the canonical `folder` or inside it.
bool contains(const fs::path& folder, const fs::path& path) {
  auto [f_end, p_at] = std::mismatch(folder.begin(), folder.end(), path.begin(), path.end());
  return f_end == folder.end();
}

// Whether `path` is `folder` or inside it (`path` made absolute, "." and ".." and links resolved).
bool inside(const fs::path& path, const fs::path& folder) { return contains(folder, fs::weakly_canonical(path)); }

// The files of a --files-from list, relative to the base folder, checked: each a file under the
// base, none under the output folder.
Result<std::vector<std::string>> listed_files(const std::string& base, const fs::path& canonical_base,
                                              const fs::path& out_folder, const std::vector<std::string>& listed) {
  std::vector<std::string> files;
  for (const std::string& entry : listed) {
    fs::path relative = fs::path(entry).lexically_normal();
    if (relative.is_absolute()) {
      const fs::path canonical = fs::weakly_canonical(relative);
      if (!contains(canonical_base, canonical))
        return usage(codes::batch::listed_outside, "listed file " + entry + " is not inside " + base);
      relative = canonical.lexically_relative(canonical_base);
    }
    if (relative.empty() || *relative.begin() == "..")
      return usage(codes::batch::listed_outside, "listed file " + entry + " is not inside " + base);
    std::error_code ec;
    if (!fs::is_regular_file(fs::path(base) / relative, ec))
      return usage(codes::batch::listed_outside, "listed file " + entry + " is not a file under " + base);
    if (contains(out_folder, canonical_base / relative))
      return usage(codes::batch::inside_output, "listed file " + entry + " is inside the output folder");
    files.push_back(relative.string());
  }
  return files;
}

}  // namespace

Result<std::vector<BatchJob>> plan_batch(const std::vector<std::string>& inputs, const std::string& out_dir,
                                         const std::vector<std::string>& kinds,
                                         const std::vector<std::string>* listed) {
  std::vector<const OutputFormat*> writers;
  for (const std::string& kind : kinds) {
    const OutputFormat* writer = formats().output_named(kind);
    if (!writer) return usage(codes::batch::unknown_output_kind, unknown_kind_message(kind, true));
    writers.push_back(writer);
  }
  if (kinds.empty()) return usage(codes::batch::no_output_kind, "no output kind in --to");
  std::error_code ec;
  if (listed && (inputs.size() != 1 || !fs::is_directory(inputs.front(), ec)))
    return usage(codes::batch::files_from_folder,
                 "--files-from takes one folder INPUT, the one its paths are relative to (none: the current folder)");
  // Checked here, not by the command line, so every caller gets it: the error names the file.
  if (fs::exists(out_dir, ec) && !fs::is_directory(out_dir, ec))
    return make_error(codes::batch::output_not_folder, Location::whole_file(out_dir),
                      "-o names an existing file, not a folder (batch writes into a folder)");
  const fs::path out_folder = fs::weakly_canonical(out_dir);
  struct Found {
    std::string input;
    std::string name;       // under DIR, without the input's extension
    std::string full_name;  // with it: for a folder's inputs that differ by extension only
  };
  std::vector<Found> found;
  for (const std::string& input : inputs) {
    if (!fs::exists(input, ec)) return usage(codes::batch::no_such_input, "no such file or folder: " + input);
    if (!fs::is_directory(input, ec)) {
      if (inside(input, out_folder))
        return usage(codes::batch::inside_output, input + " is inside the output folder " + out_dir);
      found.push_back({input, fs::path(without_input_extension(input)).filename().string(), {}});
      continue;
    }
    // The folder is made canonical once. The walk follows no symbolic link to a folder, so an
    // entry's canonical path is the folder's joined with the entry's relative path, unless the
    // entry is itself a link (then it is resolved). Resolving every entry (fs::relative and
    // fs::weakly_canonical each read every component's link) was the serial start of a
    // large batch: 20,000 readlink calls for 500 files.
    const fs::path canonical_input = fs::weakly_canonical(input);
    std::vector<std::string> files;  // relative to the folder
    if (listed) {
      auto taken = listed_files(input, canonical_input, out_folder, *listed);
      if (!taken) return taken.error();
      files = std::move(*taken);
    }
    // A listed folder is not walked (the empty iterator is the walk's end).
    for (auto it = listed ? fs::recursive_directory_iterator() : fs::recursive_directory_iterator(input);
         it != fs::recursive_directory_iterator(); ++it) {
      const fs::path relative = it->path().lexically_relative(input);
      const auto is_output = [&] {
        return it->is_symlink() ? inside(it->path(), out_folder) : contains(out_folder, canonical_input / relative);
      };
      if (it->is_directory() && is_output()) {
        it.disable_recursion_pending();  // outputs of this or an earlier run are never inputs
        continue;
      }
      if (it->is_regular_file() && formats().input_for(it->path().string()) && !is_output())
        files.push_back(relative.string());
    }
    std::sort(files.begin(), files.end());
    for (const std::string& relative : files)
      found.push_back({(fs::path(input) / relative).string(), without_input_extension(relative), relative});
  }
  std::vector<BatchJob> jobs;
  std::map<std::string, std::vector<std::string>> inputs_of;  // output -> the inputs writing it
  // A folder's `smile.fml` and `smile.mimic` keep their extensions (smile.fml.fap, smile.mimic.fap)
  // rather than clash; every other name is the input's without its extension.
  std::map<std::string, std::size_t> sharing;
  for (const Found& f : found) ++sharing[f.name];
  for (Found& f : found)
    if (sharing[f.name] > 1 && !f.full_name.empty()) f.name = f.full_name;
  for (const auto& [input, name, full_name] : found) {
    BatchJob job{input, {}};
    for (std::size_t k = 0; k < kinds.size(); ++k) {
      const std::string output =
          (fs::path(out_dir) / (name + writers[k]->extensions.front())).lexically_normal().string();
      job.outputs.push_back(OutputRequest{output, kinds[k]});
      inputs_of[output].push_back(input);
    }
    jobs.push_back(std::move(job));
  }
  std::string shared;
  for (const auto& [output, writers_of] : inputs_of) {
    if (writers_of.size() < 2) continue;
    shared += "\n  " + output + " <-";
    for (const std::string& input : writers_of) shared += " " + input;
  }
  if (!shared.empty())
    return usage(codes::batch::outputs_collide,
                 "inputs would overwrite each other's outputs; nothing converted (rename one, or convert them "
                 "in separate runs):" +
                     shared);
  return jobs;
}

namespace {

// The folders a batch made for its outputs, so that those left empty (every job writing there
// failed) can be removed at the end: a failed batch leaves nothing behind, as a failed compile
// does. Removed only once every job is done, so no job finds its folder gone.
class MadeFolders {
 public:
  // Makes `folder` and its missing parents, remembering which were missing.
  void make(const fs::path& folder, std::error_code& ec) {
    const std::lock_guard<std::mutex> lock(mutex_);
    std::vector<fs::path> missing;
    for (fs::path at = folder; !at.empty() && !fs::exists(at, ec); at = at.parent_path()) {
      missing.push_back(at);
      if (at == at.parent_path()) break;
    }
    ec.clear();
    fs::create_directories(folder, ec);
    if (!ec) made_.insert(made_.end(), missing.begin(), missing.end());
  }
  // Removes the folders made that are empty, the deepest first (a folder holding only empty
  // folders made here is empty once they are gone). A folder with anything in it stays.
  void remove_empty() {
    std::sort(made_.begin(), made_.end(), [](const fs::path& a, const fs::path& b) {
      return std::distance(a.begin(), a.end()) > std::distance(b.begin(), b.end());
    });
    for (const fs::path& folder : made_) {
      std::error_code ec;
      if (fs::is_empty(folder, ec) && !ec) fs::remove(folder, ec);
    }
  }

 private:
  std::mutex mutex_;
  std::vector<fs::path> made_;
};

// One job, whatever happens inside: an exception becomes the job's error.
BatchOutcome run_job(const BatchJob& job, const ConvertOptions& options, const BatchRunOptions& run,
                     MadeFolders& folders) {
  BatchOutcome outcome;
  const auto start = std::chrono::steady_clock::now();
  const auto finish = [&] {
    outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return std::move(outcome);
  };
  if (run.records && !run.redo_all && run.records->complete(job)) {
    outcome.up_to_date = true;
    for (const OutputRequest& output : job.outputs) outcome.result.written.push_back(output.path);
    return finish();
  }
  outcome.ran = true;
  try {
    std::optional<FileStamp> input_stamp;
    if (run.records) input_stamp = run.records->prepare(job);
    for (const OutputRequest& output : job.outputs) {
      std::error_code ec;
      const fs::path folder = fs::path(output.path).parent_path();
      if (!folder.empty()) folders.make(folder, ec);
      if (ec) {
        outcome.result.error = make_error(codes::batch::folder_not_created, Location::whole_file(folder.string()),
                                          "cannot create the folder: " + ec.message());
        break;
      }
    }
    if (!outcome.result.error)
      outcome.result = run.convert ? run.convert(job, options) : convert(job.input, job.outputs, options);
    if (run.records && outcome.result.ok())
      if (Status recorded = run.records->record(job, input_stamp); !recorded) outcome.result.error = recorded.error();
  } catch (const std::exception& e) {
    outcome.result.error = make_error(codes::batch::internal_error, Location::whole_file(job.input),
                                      std::string("internal error while converting: ") + e.what());
  } catch (...) {
    outcome.result.error = make_error(codes::batch::internal_error, Location::whole_file(job.input),
                                      "internal error while converting (unknown exception)");
  }
  return finish();
}

}  // namespace

std::vector<BatchOutcome> run_batch(const std::vector<BatchJob>& jobs, const ConvertOptions& options,
                                    const BatchRunOptions& run) {
  std::vector<BatchOutcome> outcomes(jobs.size());
  std::vector<char> finished(jobs.size(), 0);
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed_stop{false};
  std::mutex report;  // held only to hand finished jobs to the callbacks, never while converting
  std::size_t reported = 0, done = 0;
  MadeFolders folders;
  const auto stopping = [&] { return failed_stop.load() || (run.stop && run.stop->load()); };
  // Hands every job finished in input order since the last call to in_order. Under `report`.
  const auto hand_over = [&] {
    for (; reported < jobs.size() && finished[reported]; ++reported)
      if (run.in_order && (outcomes[reported].ran || outcomes[reported].up_to_date))
        run.in_order(reported, outcomes[reported]);
  };
  const auto worker = [&] {
    for (std::size_t i; !stopping() && (i = next++) < jobs.size();) {
      BatchOutcome outcome = run_job(jobs[i], options, run, folders);
      if (!outcome.result.ok() && !run.keep_going) failed_stop = true;
      const std::lock_guard<std::mutex> lock(report);
      outcomes[i] = std::move(outcome);
      finished[i] = 1;
      ++done;
      if (run.progress) run.progress(done, jobs.size());
      hand_over();
    }
  };
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  const std::size_t wanted = run.threads > 0 ? static_cast<std::size_t>(run.threads) : cores;
  const std::size_t count = std::max<std::size_t>(1, std::min(wanted, jobs.size()));
  // The speaker must be forked before the workers run (fapc/speech/engine.hpp); a no-op when the
  // caller started it already, as fapc's main does.
  if (count > 1 && options.speech_engine) speech::start_engine_process();
  std::vector<std::thread> threads;
  for (std::size_t t = 1; t < count; ++t) threads.emplace_back(worker);
  worker();  // this thread is one of the pool
  for (std::thread& t : threads) t.join();
  folders.remove_empty();
  // Jobs stopped before starting leave gaps: what ran after a gap is handed over now, in order.
  for (std::size_t i = 0; i < jobs.size(); ++i) finished[i] = 1;
  hand_over();
  return outcomes;
}

std::string batch_summary_line(const BatchJob& job, const BatchOutcome& outcome) {
  if (outcome.up_to_date) {
    std::string line = job.input + ": up to date ->";
    for (const OutputRequest& output : job.outputs) line += " " + output.path;
    return line;
  }
  if (!outcome.result.ok()) return "FAILED " + job.input;
  const ConvertResult::FramesSeen& seen = outcome.result.frames;
  std::ostringstream line;
  line << job.input << ": " << seen.count << " frames, " << seen.fps << " fps, " << seen.faps.count() << " FAPs, "
       << outcome.result.warnings.size() << " warnings ->";
  for (const std::string& output : outcome.result.written) line << ' ' << output;
  return line.str();
}

std::string junit_report(const std::vector<BatchJob>& jobs, const std::vector<BatchOutcome>& outcomes) {
  return junit_from_report(json_value(batch_report_json(jobs, outcomes, false)));
}

}  // namespace fapc::pipeline
