// What compile, render, decode and plot share around one conversion: -v's account of what was read
// and written, and the progress of a long job on a terminal.
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

}  // namespace fapc::cli
