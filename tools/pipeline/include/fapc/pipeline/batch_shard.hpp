// Shards: one batch split over several machines (docs/cluster.md). Every node plans the same
// batch and keeps the jobs of its shard, so shards are disjoint and together make the whole
// batch without any node talking to another.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "fapc/pipeline/batch.hpp"

namespace fapc::pipeline {

struct Shard {
  std::size_t index = 0;  // 0 .. count-1, as Slurm array task ids and Kubernetes indexes count
  std::size_t count = 1;
};

// The largest shard count: far above Slurm's default largest array (1001 tasks), low enough that
// a typo (a job count for a shard count) is caught.
inline constexpr std::size_t kMaxShards = 100000;

// "I/N" with 0 <= I < N <= kMaxShards; a usage error naming --shard otherwise.
Result<Shard> parse_shard(const std::string& text);

// The shard a scheduler gave this process, read through `lookup` (std::getenv in the program):
// - a Slurm array task: SLURM_ARRAY_TASK_ID; the count is `shards` when given (then the task id is
//   the shard: a task resubmitted alone, `sbatch --array=2`, keeps its shard), else
//   SLURM_ARRAY_TASK_COUNT, with the id counted from SLURM_ARRAY_TASK_MIN in steps of
//   SLURM_ARRAY_TASK_STEP (so --array=1-4 and --array=0-6:2 work too);
// - a Kubernetes indexed Job: JOB_COMPLETION_INDEX, with the count from `shards` (required: the pod
//   is not told the completion count).
// Empty without either (and without `shards`); an error when `shards` is given and no index is
// found, or when the environment's values are not numbers in range.
using EnvironmentLookup = std::function<const char*(const char* name)>;
Result<std::optional<Shard>> shard_from_environment(const EnvironmentLookup& lookup, std::optional<std::size_t> shards);

// The jobs of `shard`, in plan order. Jobs are ranked by their key (the first output's path,
// unique in a plan and the same on every node whatever order the inputs were listed in) and
// dealt round-robin, so each shard gets an even share of every folder.
std::vector<BatchJob> select_shard(const std::vector<BatchJob>& jobs, const Shard& shard);

}  // namespace fapc::pipeline
