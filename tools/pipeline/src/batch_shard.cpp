#include "fapc/pipeline/batch_shard.hpp"

#include <algorithm>
#include <charconv>
#include <numeric>

#include "fapc/pipeline/codes.hpp"

namespace fapc::pipeline {

namespace {

Diagnostic usage(const std::string& message) { return make_error(codes::batch::bad_shard, Location{}, message); }

// A whole decimal number, nothing around it.
std::optional<std::size_t> whole_number(std::string_view text) {
  std::size_t value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || ec != std::errc{} || end != text.data() + text.size()) return std::nullopt;
  return value;
}

// The environment variable `name` as a number; an error names it and its value.
Result<std::optional<std::size_t>> number_from(const EnvironmentLookup& lookup, const char* name) {
  const char* text = lookup(name);
  if (!text) return std::optional<std::size_t>{};
  if (const auto value = whole_number(text)) return std::optional<std::size_t>{*value};
  return usage(std::string("the environment's ") + name + "='" + text + "' is not a whole number");
}

Result<Shard> checked(std::size_t index, std::size_t count, const std::string& source) {
  if (count == 0 || count > kMaxShards)
    return usage(source + ": the shard count must be 1 to " + std::to_string(kMaxShards) + ", not " +
                 std::to_string(count));
  if (index >= count)
    return usage(source + ": shard " + std::to_string(index) + " of " + std::to_string(count) +
                 " does not exist (shards count from 0: 0/" + std::to_string(count) + " to " +
                 std::to_string(count - 1) + "/" + std::to_string(count) + ")");
  return Shard{index, count};
}

}  // namespace

Result<Shard> parse_shard(const std::string& text) {
  const auto slash = text.find('/');
  const auto index = whole_number(std::string_view(text).substr(0, slash));
  const auto count = slash == std::string::npos ? std::nullopt : whole_number(std::string_view(text).substr(slash + 1));
  if (!index || !count) return usage("--shard takes I/N (shard I of N, counted from 0), not '" + text + "'");
  return checked(*index, *count, "--shard " + text);
}

Result<std::optional<Shard>> shard_from_environment(const EnvironmentLookup& lookup,
                                                    std::optional<std::size_t> shards) {
  const auto given = [&](std::size_t index, std::size_t count,
                         const std::string& source) -> Result<std::optional<Shard>> {
    auto shard = checked(index, count, source);
    if (!shard) return shard.error();
    return std::optional<Shard>{*shard};
  };
  auto task = number_from(lookup, "SLURM_ARRAY_TASK_ID");
  if (!task) return task.error();
  if (*task) {
    if (shards) return given(**task, *shards, "SLURM_ARRAY_TASK_ID with --shards");
    auto count = number_from(lookup, "SLURM_ARRAY_TASK_COUNT");
    auto first = number_from(lookup, "SLURM_ARRAY_TASK_MIN");
    auto step = number_from(lookup, "SLURM_ARRAY_TASK_STEP");
    if (!count) return count.error();
    if (!first) return first.error();
    if (!step) return step.error();
    if (!*count) return usage("SLURM_ARRAY_TASK_ID is set but not SLURM_ARRAY_TASK_COUNT: give --shards N");
    const std::size_t from = first->value_or(0), by = std::max<std::size_t>(1, step->value_or(1));
    if (**task < from || (**task - from) % by != 0)
      return usage("SLURM_ARRAY_TASK_ID " + std::to_string(**task) + " is not in the array's range: give --shards N");
    return given((**task - from) / by, **count, "SLURM_ARRAY_TASK_ID/SLURM_ARRAY_TASK_COUNT");
  }
  auto pod = number_from(lookup, "JOB_COMPLETION_INDEX");
  if (!pod) return pod.error();
  if (*pod) {
    if (!shards) return usage("JOB_COMPLETION_INDEX is set: give --shards N (the Job's completions)");
    return given(**pod, *shards, "JOB_COMPLETION_INDEX with --shards");
  }
  if (shards)
    return usage("--shards " + std::to_string(*shards) +
                 " needs a shard index from SLURM_ARRAY_TASK_ID or JOB_COMPLETION_INDEX (or give --shard I/N)");
  return std::optional<Shard>{};
}

std::vector<BatchJob> select_shard(const std::vector<BatchJob>& jobs, const Shard& shard) {
  const auto key = [&](std::size_t i) -> const std::string& {
    return jobs[i].outputs.empty() ? jobs[i].input : jobs[i].outputs.front().path;
  };
  std::vector<std::size_t> ranked(jobs.size());
  std::iota(ranked.begin(), ranked.end(), std::size_t{0});
  std::sort(ranked.begin(), ranked.end(), [&](std::size_t a, std::size_t b) { return key(a) < key(b); });
  std::vector<char> mine(jobs.size(), 0);
  for (std::size_t rank = shard.index; rank < ranked.size(); rank += shard.count) mine[ranked[rank]] = 1;
  std::vector<BatchJob> out;
  for (std::size_t i = 0; i < jobs.size(); ++i)
    if (mine[i]) out.push_back(jobs[i]);
  return out;
}

}  // namespace fapc::pipeline
