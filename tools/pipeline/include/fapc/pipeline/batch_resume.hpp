// Resumable batches (docs/cluster.md, "Resuming"): after a job converts, a completion record is
// written atomically under DIR/.fapc-batch/; a re-run skips a job whose record still matches its
// input and its outputs, so a pre-empted or killed array task can simply be submitted again.
// A timestamp alone would take a half-written or stale output, or one made with other options,
// for a finished one; the record says what was finished, from what, and how.
#pragma once

#include <cstdint>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "fapc/pipeline/batch.hpp"

namespace fapc::pipeline {

// What a file was when it was read or written: enough to see it has changed since.
struct FileStamp {
  std::uintmax_t size = 0;
  std::int64_t time = 0;  // modification time, in the file clock's ticks (nanoseconds here)
  bool operator==(const FileStamp&) const = default;
};
std::optional<FileStamp> stamp_of(const std::string& path);

// The records of one batch's output folder. Jobs of other shards may share the folder: each job
// has a record of its own, and a shard only ever touches its own jobs' records and files.
class CompletionRecords {
 public:
  // `settings`: everything besides the input that decides the outputs' bytes (the conversion
  // options, the program's version): a record made under other settings is not complete.
  // `jobs`: the jobs this process runs (whose leftovers it may remove).
  CompletionRecords(std::string out_dir, std::string settings, const std::vector<BatchJob>& jobs);

  // Whether the job is finished: its record names the same settings and the same outputs, its
  // input has the size and time recorded (taken before it was converted), and every output is
  // still the file recorded (size and time).
  bool complete(const BatchJob& job) const;
  // Before a job runs: its record goes (a job half redone is not complete), and so do temporary
  // files an earlier, killed attempt left beside its outputs. Returns the input's stamp, taken
  // before converting so that an input changed during the job is redone next time.
  std::optional<FileStamp> prepare(const BatchJob& job) const;
  // After the job converted: its record, written atomically (whole or not at all).
  Status record(const BatchJob& job, const std::optional<FileStamp>& input) const;

  // DIR/.fapc-batch/<first output, relative to DIR>.done
  std::string record_path(const BatchJob& job) const;

 private:
  void sweep(const std::string& folder) const;

  std::string out_dir_;
  std::string settings_;
  // Folder -> the file names of this process's outputs and records in it: the targets whose
  // temporary files (.fapc-tmp-<pid>-<seed>-<n>-<name>) are leftovers of an earlier attempt.
  std::map<std::string, std::set<std::string>> ours_;
  mutable std::mutex swept_lock_;
  mutable std::set<std::string> swept_;  // each folder is listed once per run
};

// The folder of the records under an output folder.
inline constexpr const char* kRecordsFolder = ".fapc-batch";

}  // namespace fapc::pipeline
