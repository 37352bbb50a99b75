// Batch: many inputs to a folder of outputs, in parallel. Planning is separate from running so
// that every problem with the plan (an output two inputs would share, an output folder that is a
// file) is found before anything is converted.
#pragma once

#include <atomic>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "fapc/pipeline/convert.hpp"

namespace fapc::pipeline {

struct BatchJob {
  std::string input;
  std::vector<OutputRequest> outputs;  // one per kind, in the order the kinds were given
};

// Inputs are files (taken whatever they are: an unknown kind fails when run) and folders (their
// supported files, recursively, sorted). Outputs mirror the tree under each input folder:
// DIR/<path relative to the folder without its input extension>.<output extension> (with the
// extension kept when two of the folder's inputs differ by it only: a/smile.fml.fap beside
// a/smile.mimic.fap); a file named on its own goes to DIR/<its name without extension>.<output
// extension>. Files under DIR are
// never inputs. Errors (usage): a missing input, an unknown kind, DIR naming an existing
// non-folder, a named input inside DIR, and outputs two inputs would share (all listed).
//
// With `listed` (--files-from), `inputs` is one folder (the base) and the listed paths replace its
// walk: each is a file relative to the base (or an absolute path inside it), mirrored under DIR as
// the walk's files are, so a planner's list of a tree gives the outputs the tree itself would.
// Errors (usage) also: a listed path that is not a file, or that leaves the base.
Result<std::vector<BatchJob>> plan_batch(const std::vector<std::string>& inputs, const std::string& out_dir,
                                         const std::vector<std::string>& kinds,
                                         const std::vector<std::string>* listed = nullptr);

class CompletionRecords;  // batch_resume.hpp

struct BatchOutcome {
  bool ran = false;         // false: stopped before this job started, or up to date
  bool up_to_date = false;  // not run: its completion record says its outputs are complete
  ConvertResult result;
  double seconds = 0;
};

struct BatchRunOptions {
  int threads = 1;          // 0: one per core
  bool keep_going = false;  // false: the first failure stops jobs not yet started
  // Set (by a signal handler, say) to stop: jobs not started are skipped, outputs of running
  // jobs are finished or not written at all (never a partial or temporary file).
  const std::atomic<bool>* stop = nullptr;
  // Called once per job that ran or was up to date, in input order, never two at a time, as soon as the job and
  // every job before it are done: callers print here. Runs on a worker thread.
  std::function<void(std::size_t index, const BatchOutcome&)> in_order;
  // Called as each job finishes (any order, never two at a time): for progress.
  std::function<void(std::size_t finished, std::size_t total)> progress;
  // The work of one job; empty: convert(job.input, job.outputs, options). Whatever it throws is
  // the job's error.
  std::function<ConvertResult(const BatchJob&, const ConvertOptions&)> convert;
  // Resumable runs (batch_resume.hpp): a job whose record says it is complete is not run, and a
  // job that converts gets its record. Null: every job runs and nothing is recorded.
  const CompletionRecords* records = nullptr;
  bool redo_all = false;  // --force: run every job, up to date or not (records are still written)
};

// Runs the jobs on a pool of std::threads. A job that throws is a failed job (its error says
// so), never the end of the batch.
std::vector<BatchOutcome> run_batch(const std::vector<BatchJob>& jobs, const ConvertOptions& options,
                                    const BatchRunOptions& run);

// "INPUT: N frames, F fps, K FAPs, W warnings -> OUT...", "INPUT: up to date -> OUT..." or
// "FAILED INPUT".
std::string batch_summary_line(const BatchJob& job, const BatchOutcome& outcome);

// A JUnit XML report: one test case per job that ran or was up to date, failures with their error
// (made from batch_report_json: batch_merge.hpp writes merged reports the same way).
std::string junit_report(const std::vector<BatchJob>& jobs, const std::vector<BatchOutcome>& outcomes);

}  // namespace fapc::pipeline
