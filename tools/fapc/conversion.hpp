// What compile, render and decode share around one conversion: -v's account of what was read
// and written, the progress of a long job on a terminal, and standard output for -o -.
#pragma once

#include <chrono>
#include <memory>
#include <string>

#include "fapc/pipeline/convert.hpp"
#include "fapc/progress.hpp"

namespace fapc::cli {

// Started before the work: the progress bar (on a terminal) fed by options.progress, and the clock
// -v reports.
class ConversionWatch {
 public:
  explicit ConversionWatch(pipeline::ConvertOptions& options);
  // -v: "read IN (kind, N frames at F fps); wrote OUT... in 0.12 s".
  void tell_done(const std::string& input, const pipeline::ConvertResult& result) const;

 private:
  std::shared_ptr<ProgressBar> bar_;
  std::chrono::steady_clock::time_point start_;
};

// Converts `input` (the operand as resolved: a copy of standard input is a temporary file) to
// one output with the watch around it, reports the diagnostics, writes standard output for -o -.
// `named` is the operand as the user gave it. Returns the exit status.
int convert_one(const std::string& named, const std::string& input, const std::string& output, const std::string& to,
                pipeline::ConvertOptions& options);

}  // namespace fapc::cli
