// What the cluster tests share besides the pipeline tests' TempFolder: fapc run through the shell, and a
// folder's outputs as a map of relative path to bytes (the completion records left out), which
// is what "the same outputs" means for a sharded or resumed batch.
#pragma once

#include <filesystem>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "pipeline/pipeline_test_helpers.hpp"
#include "support/test_support.hpp"

namespace fapc::test {

// Every file under `folder` but the completion records, by path relative to it.
inline std::map<std::string, std::string> outputs_under(const std::string& folder) {
  std::map<std::string, std::string> out;
  if (!std::filesystem::is_directory(folder)) return out;
  for (auto it = std::filesystem::recursive_directory_iterator(folder);
       it != std::filesystem::recursive_directory_iterator(); ++it) {
    if (it->path().filename() == ".fapc-batch") {
      it.disable_recursion_pending();
      continue;
    }
    if (it->is_regular_file()) out[it->path().lexically_relative(folder).string()] = read_text(it->path().string());
  }
  return out;
}

// The differences between two batches' outputs: files missing on one side, and bytes that differ.
// Talk included: each utterance is spoken from the same engine state, whatever its process said
// before (docs/cluster.md, "Speech").
inline std::string output_differences(const std::string& a, const std::string& b) {
  const auto left = outputs_under(a), right = outputs_under(b);
  std::string out;
  for (const auto& [path, bytes] : left) {
    const auto other = right.find(path);
    if (other == right.end())
      out += "only in " + a + ": " + path + "\n";
    else if (other->second != bytes)
      out += "differs: " + path + "\n";
  }
  for (const auto& [path, bytes] : right)
    if (!left.count(path)) out += "only in " + b + ": " + path + "\n";
  return out;
}

// `fapc ARGS` from the source folder, with shell syntax allowed around it (pipes, environment).
inline CommandRun fapc_shell(const std::string& before, const std::string& args) {
  return run_shell("cd '" + source_dir() + "' && " + before + " '" + fapc_program() + "' " + args);
}

}  // namespace fapc::test
