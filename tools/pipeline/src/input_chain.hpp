// Inputs that include inputs (docs/security.md): the chain of inputs being read on this thread,
// for cycles, the depth limit and the folders includes may read.
#pragma once

#include <string>
#include <vector>

#include "fapc/pipeline/loaded.hpp"
#include "fapc/pipeline/options.hpp"

namespace fapc::pipeline {

// While alive, `path` is an input being read on this thread (load() makes one; so does anything
// that calls a format's load itself). The top input puts its folder (for standard input,
// includes.base_folder) among the folders includes may read; an included input takes its
// relative names from its own folder.
class ReadingInput {
 public:
  ReadingInput(const std::string& path, const ConvertOptions& options);
  ~ReadingInput();
  ReadingInput(const ReadingInput&) = delete;
  ReadingInput& operator=(const ReadingInput&) = delete;
  const ConvertOptions& options() const { return options_; }

 private:
  ConvertOptions options_;
};

// The inputs being read on this thread, outermost first, as their paths were given.
std::vector<std::string> inputs_being_read();

// An input that the one being read includes, named at `where`. One already being read is a cycle,
// an error at `where` naming the chain ("a.combine -> b.combine -> a.combine"); deeper than
// kMaxIncludeDepth is a limit. The input is read on a fresh stack of its own, so that each level
// of including has the whole stack its own bounded recursion needs.
Result<Loaded> load_included_input(const std::string& path, const Location& where, const ConvertOptions& options);

}  // namespace fapc::pipeline
