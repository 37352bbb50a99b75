// How a long .fap reaches .fba and .fap outputs without its frames in memory
// (docs/architecture.md, "Streaming"). The FBA encoder needs two passes over the frames (the first
// checks them and gathers what fitting masks needs, the second codes), and the .fap reader knows
// what its frame numbers mean only at the end of the file; so the file is read twice from one
// mapping whose pages are let go behind the reader:
//
//   pass 1: scan_fap_text  --frames-->  FbaEncoder::check       every error and warning found
//   pass 2: scan_fap_text  --frames, numbered as placed-->  FbaEncoder::add, FapTextWriter::add
//
// The encoder's bytes stay in memory (a few bits a frame); the .fap text goes to a temporary file
// in the output's folder, renamed over it only when everything has succeeded.
#include "streamed_convert.hpp"

#include "fapc/codec/fap_file.hpp"
#include "fapc/codec/fba.hpp"
#include "fapc/codec/file_io.hpp"
#include "fapc/pipeline/fba_io.hpp"

namespace fapc::pipeline {

namespace {

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

bool can_stream(const std::string& input, const std::vector<OutputRequest>& outputs,
                const std::vector<const OutputFormat*>& writers, const ConvertOptions& options) {
  const InputFormat* format = formats().input_for(input);
  if (input == "-" || !format || format->kind != "fap" || options.verify || options.facts || outputs.empty())
    return false;
  for (std::size_t i = 0; i < outputs.size(); ++i)
    if ((writers[i]->kind != "fba" && writers[i]->kind != "fap") || outputs[i].path == "-" ||
        ends_with(outputs[i].path, ".gz"))
      return false;
  return true;
}

// The .fap text in pieces, to the temporary file of every .fap output.
class FapOutputs {
 public:
  FapOutputs(const FapScanResult& scan, const ConvertOptions& options)
      : writer(scan.read.sequence.name, scan.read.sequence.fps, scan.numbers.size(),
               scan.numbers.empty() ? 0 : scan.numbers.front(), scan.numbers.empty() ? 0 : scan.numbers.back(),
               write_options(options)) {}

  static FapWriteOptions write_options(const ConvertOptions& options) {
    FapWriteOptions write;
    write.flavour = options.fap_flavour;
    return write;
  }

  // A temporary file for output `i`; its error, if any, is that output's.
  void open(std::size_t i, const std::string& path) {
    auto file = AtomicFile::create(path);
    if (file) files.emplace_back(i, std::move(*file));
    else failed.emplace_back(i, file.error());
  }
  bool any() const { return !files.empty(); }

  // Hands the text made so far to every file (`always`, or once it passes 1 MB).
  void flush(bool always) {
    if (!always && text.size() < (std::size_t{1} << 20)) return;
    for (auto& [i, file] : files)
      if (auto written = file.write(text); !written && !error_of(i)) failed.emplace_back(i, written.error());
    text.clear();
  }

  const Diagnostic* error_of(std::size_t i) const {
    for (const auto& [at, why] : failed)
      if (at == i) return &why;
    return nullptr;
  }
  AtomicFile& file_of(std::size_t i) {
    for (auto& [at, file] : files)
      if (at == i) return file;
    return files.front().second;  // not reached: every .fap output has a file or an error
  }

  FapTextWriter writer;
  std::string text;                 // made, not yet written
  std::optional<Diagnostic> error;  // the writer's: the flavour cannot carry a frame
  std::vector<std::pair<std::size_t, AtomicFile>> files;  // by output index
  std::vector<std::pair<std::size_t, Diagnostic>> failed;  // outputs whose file failed
};

}  // namespace

std::optional<ConvertResult> convert_streamed(const std::string& input, const std::vector<OutputRequest>& outputs,
                                              const std::vector<const OutputFormat*>& writers,
                                              const ConvertOptions& options) {
  if (!can_stream(input, outputs, writers, options)) return std::nullopt;
  auto mapped = MappedFile::open(input);
  if (!mapped || is_gzip(mapped->bytes())) return std::nullopt;  // the usual way reports it, or inflates it
  const std::string_view text = mapped->bytes();
  const auto let_go = [&](std::size_t offset) { mapped->release(offset); };
  FapReadOptions read_options;
  read_options.max_frames = options.limits.max_frames;
  bool wants_fba = false;
  for (const OutputFormat* writer : writers) wants_fba = wants_fba || writer->kind == "fba";

  // Pass 1. The encoder checks each frame as it comes; its error, if any, is the one writing the
  // .fba would give, so it waits until the reading has succeeded (reading errors come first). It
  // sees the frames numbered in order: the reader itself checks what the numbers mean (ascending,
  // within the frame limit: the encoder's checks of numbers) once it has them all.
  // The encoder's errors about one frame point at its line, known once the first pass is done.
  const FapScanResult* scanned = nullptr;
  FbaEncodeOptions encode_options = fba_encode_options(options);
  encode_options.locate = [&](std::int64_t number, int fap) {
    const auto locate = scanned ? frame_locator(scanned->numbers, scanned->read.value_lines, input) : nullptr;
    return locate ? locate(number, fap) : Location{};
  };
  std::optional<FbaEncoder> encoder;
  if (wants_fba) encoder.emplace(encode_options);
  std::optional<Diagnostic> encode_error;
  std::int64_t ordinal = 0;
  std::bitset<kFapCount> faps;
  const auto check = [&](const FapFrame& frame) -> Status {
    faps |= frame.mask;
    if (!encoder || encode_error) return ok_status();
    FapFrame in_order = frame;
    in_order.number = ordinal++;
    if (auto status = encoder->check(in_order); !status) encode_error = status.error();
    return ok_status();
  };
  auto scan = scan_fap_text(text, input, read_options, check, let_go);
  ConvertResult result;
  if (!scan) {
    result.error = scan.error();
    return result;
  }
  scanned = &*scan;
  result.warnings = scan->read.warnings;
  result.loaded.origin = input;
  result.loaded.frames.name = scan->read.sequence.name;
  result.loaded.frames.fps = scan->read.sequence.fps;
  result.loaded.warnings = scan->read.warnings;
  result.frames = {scan->numbers.size(), scan->read.sequence.fps, faps};
  if (options.strict && !result.warnings.empty()) {
    result.error = make_error(ErrorKind::bad_input, Location{input, 0, 0, -1},
                              std::to_string(result.warnings.size()) +
                                  " warning(s) treated as errors (--strict); nothing written");
    return result;
  }
  if (encoder && !encode_error)
    if (auto status = encoder->start(scan->read.sequence.fps); !status) encode_error = status.error();

  // Pass 2: the frames again, numbered as placed in time, to the encoder and the .fap text.
  FapOutputs fap(*scan, options);
  for (std::size_t i = 0; i < outputs.size(); ++i)
    if (writers[i]->kind == "fap") fap.open(i, outputs[i].path);
  const bool wants_text = fap.any();
  if (wants_text)
    if (auto status = fap.writer.begin(fap.text); !status) fap.error = status.error();
  std::size_t k = 0;
  const auto code = [&](const FapFrame& read) -> Status {
    FapFrame frame = read;
    frame.number = scan->numbers[k++];
    if (encoder && !encode_error)
      if (auto status = encoder->add(frame); !status) encode_error = status.error();
    if (wants_text && !fap.error) {
      if (auto status = fap.writer.add(frame, fap.text); !status) fap.error = status.error();
      else fap.flush(false);
    }
    return ok_status();
  };
  if ((encoder && !encode_error) || wants_text) {
    auto again = scan_fap_text(text, input, read_options, code, let_go);
    if (!again || k != scan->numbers.size()) {
      result.error = make_error(ErrorKind::io, Location{input, 0, 0, -1}, "the file changed while it was read");
      return result;
    }
  }
  if (wants_text && !fap.error) {
    fap.writer.finish(fap.text);
    fap.flush(true);
  }
  std::optional<EncodedFba> encoded;
  if (encoder && !encode_error) {
    auto finished = encoder->finish();
    if (finished) encoded = std::move(*finished);
    else encode_error = finished.error();
  }
  if (encode_error && encode_error->where.file.empty()) encode_error->where.file = input;  // as encode_checked

  // The outputs in request order, up to the first that failed (as the usual way writes them).
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    const std::string& path = outputs[i].path;
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
      if (fap.error) {
        result.error = Diagnostic{fap.error->severity, Location{path, 0, 0, -1}, fap.error->message, {}, fap.error->kind};
        return result;
      }
      if (const Diagnostic* failed = fap.error_of(i)) {
        result.error = *failed;
        return result;
      }
      if (auto committed = fap.file_of(i).commit(); !committed) {
        result.error = committed.error();
        return result;
      }
    }
    result.written.push_back(path);
  }
  return result;
}

}  // namespace fapc::pipeline
