#include "fapc/conversion.hpp"

#include <cstdio>

#include "fapc/commands.hpp"
#include "fapc/report.hpp"
#include "fapc/streams.hpp"

namespace fapc::cli {

ConversionWatch::ConversionWatch(pipeline::ConvertOptions& options)
    : bar_(std::make_shared<ProgressBar>(progress_wanted())), start_(std::chrono::steady_clock::now()) {
  if (bar_->enabled())
    options.progress = [bar = bar_](std::string_view stage, std::int64_t done, std::int64_t total) {
      bar->update(stage, done, total);
    };
}

void ConversionWatch::tell_done(const std::string& input, const pipeline::ConvertResult& result) const {
  if (verbosity() != Verbosity::verbose) return;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  char timing[32];
  std::snprintf(timing, sizeof timing, "%.3f s", seconds);
  // result.frames, not result.loaded: a streamed conversion holds no frames.
  std::string message = "read " + input + " (" + std::to_string(result.frames.count) + " frames at " +
                        std::to_string(result.frames.fps) + " fps)";
  for (const std::string& path : result.written) message += "; wrote " + path;
  if (!result.standard_output.empty())
    message += "; " + std::to_string(result.standard_output.size()) + " bytes for standard output";
  tell(message + " in " + timing);
}

int convert_one(const std::string& named, const std::string& input, const std::string& output, const std::string& to,
                pipeline::ConvertOptions& options) {
  const ConversionWatch watch(options);
  const pipeline::ConvertResult result = pipeline::convert(input, {{output, to}}, options);
  const int status = report_outcome(result.warnings, result.error);
  watch.tell_done(named, result);
  if (status == kExitOk && output == "-" && !write_standard_output(result.standard_output)) return kExitBadInput;
  return status;
}

}  // namespace fapc::cli
