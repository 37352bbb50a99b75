// How a script reaches .fba and .fap outputs without its frames in memory (docs/architecture.md,
// "Streaming"). The front end lowers the script to its timeline as usual; the frames are then
// rendered one at a time. An .fba takes them twice (the encoder's first pass checks every frame
// and plans the masks over the whole sequence, its second codes): the first pass keeps them on a
// compact tape (frame_tape.hpp) that the second replays, or, when the tape would outgrow its
// budget, the second renders them again (rendering the same timeline gives the same frames):
//
//   pass 1: FrameStream::frame  --frames-->  FbaEncoder::check, FrameTape   every warning found here
//   pass 2: FrameTape (or FrameStream::frame)  --frames-->  FbaEncoder::add, FapTextWriter::add
//
// Without an .fba the first pass is the writing pass. The .fap text goes to a temporary file in
// the output's folder, renamed over it only when everything has succeeded; a frame costs a few
// bits of encoder output and nothing else.
#include "streamed_render.hpp"

#include <algorithm>

#include "fapc/codec/fap_file.hpp"
#include "fapc/codec/fba.hpp"
#include "fapc/codec/file_io.hpp"
#include "fapc/pipeline/fba_io.hpp"
#include "fap_text_outputs.hpp"
#include "frame_tape.hpp"
#include "timeline_input.hpp"

namespace fapc::pipeline {

namespace {

bool is_gzip_path(const std::string& path) {
  return path.size() >= 3 && path.compare(path.size() - 3, 3, ".gz") == 0;
}

bool can_stream(const std::string& input, const std::vector<OutputRequest>& outputs,
                const std::vector<const OutputFormat*>& writers, const ConvertOptions& options) {
  const InputFormat* format = reader_for(input, options);
  if (input == "-" || !format || options.verify || options.facts || outputs.empty()) return false;
  if (format->kind != "mimic" && format->kind != "fml" && format->kind != "xmt") return false;
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    if ((writers[i]->kind != "fba" && writers[i]->kind != "fap") || outputs[i].path == "-" ||
        is_gzip_path(outputs[i].path))
      return false;
    // A rate the stream cannot code is refused by the usual way, against the input.
    if (writers[i]->kind == "fba" && (options.fps < 1 || options.fps > kMaxFbaFrameRate)) return false;
  }
  return true;
}

}  // namespace

std::optional<ConvertResult> convert_script_streamed(const std::string& input,
                                                     const std::vector<OutputRequest>& outputs,
                                                     const std::vector<const OutputFormat*>& writers,
                                                     const ConvertOptions& options) {
  if (!can_stream(input, outputs, writers, options)) return std::nullopt;
  const auto steps = static_cast<std::int64_t>(outputs.size()) + 1;
  if (options.progress) options.progress("reading " + input, 0, steps);
  ConvertResult result;
  // The front end alone: the timeline, its warnings, no frames and no curves.
  ConvertOptions lower_only = options;
  lower_only.render = false;
  lower_only.renders_later = true;
  lower_only.curves = false;
  Result<Loaded> lowered = load(input, lower_only);
  if (!lowered) {
    result.error = lowered.error();
    return result;
  }
  if (!lowered->timeline) return std::nullopt;  // not reached: a script's load keeps its timeline
  // Held apart so that both can go once the tape holds every frame (the second pass needs neither).
  auto timeline = std::make_unique<Timeline>(std::move(*lowered->timeline));
  lowered->timeline.reset();
  Result<Profile> profile = profile_for(options);
  if (!profile) {
    result.error = profile.error();
    return result;
  }
  std::optional<FrameStream> stream;
  if (Result<FrameStream> started = stream_frames(*timeline, input, *profile, options); started) {
    stream.emplace(std::move(*started));
  } else {
    result.error = started.error();
    return result;
  }
  if (auto audio = mixed_audio(*timeline, options); !audio) {
    result.error = audio.error();
    return result;
  }

  bool wants_fba = false;
  for (const OutputFormat* writer : writers) wants_fba = wants_fba || writer->kind == "fba";
  std::optional<FbaEncoder> encoder;
  if (wants_fba) encoder.emplace(fba_encode_options(options));
  std::optional<Diagnostic> encode_error;
  FapTextOutputs fap(stream->name(), stream->fps(), static_cast<std::size_t>(stream->count()), 0,
                     std::max<std::int64_t>(stream->count() - 1, 0), options);
  for (std::size_t i = 0; i < outputs.size(); ++i)
    if (writers[i]->kind == "fap") fap.open(i, outputs[i].path);
  const bool wants_text = fap.any();

  // Pass 1: every frame, to the encoder's check (or, without an .fba, to the .fap text).
  std::bitset<kFapCount> faps;
  if (wants_text && !wants_fba) fap.begin();
  FrameTape tape(wants_fba ? kFrameTapeBudget : 0);
  for (std::int64_t k = 0; k < stream->count(); ++k) {
    const FapFrame frame = stream->frame(k);
    faps |= frame.mask;
    if (wants_fba) tape.record(frame);
    if (encoder && !encode_error)
      if (auto status = encoder->check(frame); !status) encode_error = status.error();
    if (wants_text && !wants_fba) fap.add(frame);
  }
  result.loaded.origin = input;
  result.loaded.frames.name = stream->name();
  result.loaded.frames.fps = stream->fps();
  result.loaded.warnings = std::move(lowered->warnings);
  result.loaded.warnings.insert(result.loaded.warnings.end(), stream->warnings().begin(), stream->warnings().end());
  result.warnings = result.loaded.warnings;
  result.frames = {static_cast<std::size_t>(stream->count()), stream->fps(), faps};
  if (options.strict && !result.warnings.empty()) {
    result.error = strict_error(input, result.warnings.size());
    return result;
  }

  // Pass 2: the same frames again, coded. From the tape the timeline and its index are no longer
  // needed: their memory goes to the encoder's group of frames.
  const std::int64_t count = stream->count();
  if (encoder && !encode_error)
    if (auto status = encoder->start(stream->fps()); !status) encode_error = status.error();
  if (wants_fba && !tape.dropped()) {
    stream.reset();
    timeline.reset();
  }
  if (wants_fba && ((encoder && !encode_error) || wants_text)) {
    if (wants_text) fap.begin();
    FrameTape::Player replay = tape.play();
    for (std::int64_t k = 0; k < count; ++k) {
      const FapFrame frame = tape.dropped() ? stream->frame(k) : replay.next();
      if (encoder && !encode_error)
        if (auto status = encoder->add(frame); !status) encode_error = status.error();
      if (wants_text) fap.add(frame);
    }
  }
  if (wants_text) fap.finish();
  std::optional<EncodedFba> encoded;
  if (encoder && !encode_error) {
    auto finished = encoder->finish();
    if (finished) encoded = std::move(*finished);
    else encode_error = finished.error();
  }
  if (encode_error) encode_error->where.file = input;  // as encode_checked names the input

  // The outputs in request order, up to the first that failed (as the usual way writes them).
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    const std::string& path = outputs[i].path;
    if (options.progress) options.progress("writing " + path, static_cast<std::int64_t>(i) + 1, steps);
    if (writers[i]->kind == "fba") {
      if (encode_error) {
        result.error = encode_error;
        return result;
      }
      const std::string_view bytes(reinterpret_cast<const char*>(encoded->bytes.data()), encoded->bytes.size());
      if (auto written = write_file_atomic(path, bytes); !written) {
        result.error = written.error();
        return result;
      }
    } else {
      if (auto failed = fap.error_of(i, path)) {
        result.error = failed;
        return result;
      }
      if (auto committed = fap.commit(i); !committed) {
        result.error = committed.error();
        return result;
      }
    }
    result.written.push_back(path);
  }
  if (options.progress) options.progress("done", steps, steps);
  return result;
}

}  // namespace fapc::pipeline
