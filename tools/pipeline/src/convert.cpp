#include "fapc/pipeline/convert.hpp"

#include <algorithm>
#include <filesystem>

#include "fap_text_outputs.hpp"
#include "fapc/codec/file_io.hpp"
#include "streamed_convert.hpp"

namespace fapc::pipeline {

Result<const OutputFormat*> writer_for(const OutputRequest& request) {
  const OutputFormat* writer =
      request.kind.empty() ? formats().output_for(request.path) : formats().output_named(request.kind);
  if (writer) return writer;
  return unknown_output_kind(request.path, request.kind);
}

FramesSeen frames_seen(const Loaded& loaded) {
  if (loaded.frames_not_kept) return *loaded.frames_not_kept;
  const FapSequence& sequence = loaded.frames;
  FramesSeen seen{sequence.frames.size(), sequence.fps, {}, {}};
  for (const FapFrame& frame : sequence.frames) seen.faps |= frame.mask;
  if (!sequence.frames.empty()) seen.last_number = sequence.frames.back().number;
  return seen;
}

Result<std::string> render_output(const Loaded& loaded, const OutputRequest& request, const ConvertOptions& options) {
  auto writer = writer_for(request);
  if (!writer) return writer.error();
  return (*writer)->write(loaded, request.path, options);
}

namespace {

// Writes every output, the writers having been found already.
void write_all(ConvertResult& result, const std::vector<const OutputFormat*>& writers,
               const std::vector<OutputRequest>& outputs, const ConvertOptions& options) {
  // What the outputs lose is said (and refused under --strict) before anything is written.
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    if (!writers[i]->losses) continue;
    for (Diagnostic& d : writers[i]->losses(result.loaded, outputs[i].path)) result.warnings.push_back(std::move(d));
  }
  if (options.strict && !result.warnings.empty()) {
    result.error = strict_error(result.loaded.named(outputs.front().path), result.warnings.size());
    return;
  }
  // Progress counts the read (done before this) and each output written.
  const auto total = static_cast<std::int64_t>(outputs.size()) + 1;
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    if (options.progress) options.progress("writing " + outputs[i].path, static_cast<std::int64_t>(i) + 1, total);
    auto bytes = writers[i]->write(result.loaded, outputs[i].path, options);
    if (!bytes) {
      result.error = bytes.error();
      return;
    }
    if (outputs[i].path == "-") {
      result.standard_output += *bytes;
      continue;
    }
    if (auto written = write_file_atomic(outputs[i].path, *bytes); !written) {
      result.error = written.error();
      return;
    }
    result.written.push_back(outputs[i].path);
  }
  if (options.progress) options.progress("done", total, total);
}

// Every writer, or the first unknown kind or output that cannot be written (a directory, a
// block device): a typo in -o should not cost a long compile.
std::optional<Diagnostic> find_writers(const std::vector<OutputRequest>& outputs,
                                       std::vector<const OutputFormat*>& writers) {
  for (const OutputRequest& request : outputs) {
    auto writer = writer_for(request);
    if (!writer) return writer.error();
    if (auto writable = check_output_path(request.path); !writable) return writable.error();
    writers.push_back(*writer);
  }
  return std::nullopt;
}

}  // namespace

ConvertResult write_outputs(Loaded loaded, const std::vector<OutputRequest>& outputs, const ConvertOptions& options) {
  ConvertResult result;
  result.loaded = std::move(loaded);
  result.frames = frames_seen(result.loaded);
  std::vector<const OutputFormat*> writers;
  if ((result.error = find_writers(outputs, writers))) return result;
  write_all(result, writers, outputs, options);
  return result;
}

namespace {

ConvertResult convert_with(const std::string& input, const std::vector<OutputRequest>& outputs,
                           const std::vector<const OutputFormat*>& writers, const ConvertOptions& options);

}  // namespace

ConvertResult convert(const std::string& input, const std::vector<OutputRequest>& outputs,
                      const ConvertOptions& options) {
  ConvertResult result;
  std::vector<const OutputFormat*> writers;
  if ((result.error = find_writers(outputs, writers))) return result;
  // Options the input's kind does not read are said first, and refused under --strict before
  // anything is read.
  Diagnostics unread = options_not_read(input, writers, options);
  if (options.strict && !unread.empty()) {
    result.warnings = std::move(unread);
    result.error = strict_error(input, result.warnings.size());
    return result;
  }
  result = convert_with(input, outputs, writers, options);
  result.warnings.insert(result.warnings.begin(), unread.begin(), unread.end());
  return result;
}

namespace {

ConvertResult convert_with(const std::string& input, const std::vector<OutputRequest>& outputs,
                           const std::vector<const OutputFormat*>& writers, const ConvertOptions& options) {
  ConvertResult result;
  // The one engine: when the input's row gives a frame source and every writer's row takes frames
  // one at a time, they go through without the frames in memory; else the input is loaded whole
  // (and, a script, rendered) and each writer gets the loaded value.
  if (auto streamed = convert_streamed(input, outputs, writers, options)) return std::move(*streamed);
  if (options.progress) options.progress("reading " + input, 0, static_cast<std::int64_t>(outputs.size()) + 1);
  // Curves only when a writer reads them (the curves JSON, the plots): half of a script's compile.
  // A script's frames are kept only when a writer reads them; else they are rendered and dropped,
  // one at a time, for their warnings and the summary.
  ConvertOptions load_options = options;
  load_options.curves =
      std::any_of(writers.begin(), writers.end(), [](const OutputFormat* w) { return w->uses_curves; });
  load_options.frames =
      std::any_of(writers.begin(), writers.end(), [](const OutputFormat* w) { return w->uses_frames; });
  // The outputs' limits on the length (a video's pictures), before a script's frames are made.
  load_options.check_length = [&writers, &outputs, &options](std::int64_t frames, int fps, const Location& ends) {
    for (std::size_t i = 0; i < writers.size(); ++i)
      if (writers[i]->check_length)
        if (Status fits = writers[i]->check_length(frames, fps, ends, outputs[i].path, options); !fits) return fits;
    return ok_status();
  };
  auto loaded = load(input, load_options);
  if (!loaded) {
    result.error = loaded.error();
    return result;
  }
  result.loaded = std::move(*loaded);
  result.frames = frames_seen(result.loaded);
  result.warnings = result.loaded.warnings;
  if (options.strict && !result.warnings.empty()) {
    result.error = strict_error(input, result.warnings.size());
    return result;
  }
  write_all(result, writers, outputs, options);
  return result;
}

}  // namespace

}  // namespace fapc::pipeline
