// What the cluster tests share besides the pipeline tests' TempFolder: fapc run through the shell, and a
// folder's outputs as a map of relative path to bytes (the completion records left out), which
// is what "the same outputs" means for a sharded or resumed batch.
#pragma once

#include <filesystem>
#include <map>
#include <regex>
#include <string>

#include <gtest/gtest.h>

#include "pipeline/pipeline_test_helpers.hpp"
#include "support/test_support.hpp"

namespace fapc::test {

// Every file under `folder` but the completion records, by path relative to it.
inline std::map<std::string, std::string> outputs_under(const std::string& folder) {
  std::map<std::string, std::string> out;
  if (!std::filesystem::is_directory(folder)) return out;
  for (auto it = std::filesystem::recursive_directory_iterator(folder); it != std::filesystem::recursive_directory_iterator(); ++it) {
    if (it->path().filename() == ".fapc-batch") {
      it.disable_recursion_pending();
      continue;
    }
    if (it->is_regular_file()) out[it->path().lexically_relative(folder).string()] = read_text(it->path().string());
  }
  return out;
}

// Whether the output `relative` (under an output folder of a batch over corpus/examples) comes
// from talk: an .fml or .xmt beside it in the examples with a <talk> (or <fml:talk>) element.
inline bool spoken(const std::string& relative) {
  for (const char* extension : {".fml", ".xmt"}) {
    const std::string input =
        corpus_dir() + "/examples/" + std::filesystem::path(relative).replace_extension(extension).string();
    if (std::filesystem::is_regular_file(input) && std::regex_search(read_text(input), std::regex("<([A-Za-z]+:)?talk[ >]")))
      return true;
  }
  return false;
}

// The differences between two batches' outputs over corpus/examples: files missing on one side,
// and bytes that differ. Talk is compared by presence only: eSpeak NG carries state from one
// utterance to the next within a process (the same text said twice in a row comes out a sample
// or two longer or shorter), so a talk's voice and mouth depend on what its process said before,
// in one batch as in a shard (docs/cluster.md, "Speech").
inline std::string output_differences(const std::string& a, const std::string& b) {
  const auto left = outputs_under(a), right = outputs_under(b);
  std::string out;
  for (const auto& [path, bytes] : left) {
    const auto other = right.find(path);
    if (other == right.end()) out += "only in " + a + ": " + path + "\n";
    else if (other->second != bytes && !spoken(path)) out += "differs: " + path + "\n";
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
