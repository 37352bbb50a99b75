// How a long frame file reaches .fba, .mp4 and .fap outputs without its frames in memory
// (docs/architecture.md, "Streaming"). The FBA encoder needs two passes over the frames (the first
// checks them and gathers what fitting masks needs, the second codes), the .fap writer needs the
// frame count for its header, and the .fap reader knows what its frame numbers mean only at the
// end of the file; so the frames are taken twice. The first pass reads the input from a mapping
// whose pages are let go behind the reader and keeps the frames on a compact tape; the second
// replays the tape, or, when the frames outgrew the tape's budget, reads the input again:
//
//   pass 1: a .fap read (scan_fap_text) or a .fba decoded  --frames-->  FbaEncoder::check, FrameTape
//   pass 2: FrameTape (or the input again), frames numbered as placed in time
//                                                          --frames-->  FbaEncoder::add, FapTextWriter::add
//
// The coded bytes stay in memory (a few bytes a frame); the .fap text goes to a temporary file in
// the output's folder as it is made, the .mp4 (whose moov, before mdat, holds every sample's size)
// once the stream is coded; each is renamed over its output only when everything has succeeded.
#include "streamed_convert.hpp"

#include <filesystem>
#include <memory>

#include "fapc/codec/fap_file.hpp"
#include "fapc/codec/fba.hpp"
#include "fapc/codec/file_io.hpp"
#include "fapc/mpeg4/mp4_writer.hpp"
#include "fapc/pipeline/fba_io.hpp"
#include "fap_text_outputs.hpp"
#include "frame_tape.hpp"

namespace fapc::pipeline {

namespace {

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

bool can_stream(const std::string& input, const std::vector<OutputRequest>& outputs,
                const std::vector<const OutputFormat*>& writers, const ConvertOptions& options) {
  const InputFormat* format = formats().input_for(input);
  if (input == "-" || !format || (format->kind != "fap" && format->kind != "fba") || options.facts || outputs.empty())
    return false;
  for (std::size_t i = 0; i < outputs.size(); ++i)
    if ((writers[i]->kind != "fba" && writers[i]->kind != "fap" && writers[i]->kind != "mp4") ||
        outputs[i].path == "-" || ends_with(outputs[i].path, ".gz"))
      return false;
  return true;
}

// What the first pass learnt about the frames, as loading would have given it.
struct SourceFacts {
  std::string name;  // the sequence's name (the .fap header's, or the file's stem)
  int fps = 25;
  Location rate_at;  // where the input wrote the rate, if it did
  Diagnostics warnings;
  std::size_t frames = 0;
  std::int64_t first_number = 0, last_number = 0;  // as placed in time
};

// A frame file read once, its frames kept on a tape for the second pass, or read twice when the
// tape would outgrow its budget. The first pass hands the frames to `check` numbered so that the
// encoder's checks of numbers hold (a .fap's numbers mean something only once it is all read: its
// reader checks them itself); the second hands them numbered as placed in time. Reading errors
// come from the first pass.
class FrameSource {
 public:
  virtual ~FrameSource() = default;
  // `onto_tape`: the frames are kept for the second pass (within the tape's budget).
  Result<SourceFacts> first_pass(const FapFrameSink& check, bool onto_tape) {
    if (!onto_tape) return read(check);
    tape_.emplace(kFrameTapeBudget);
    return read([&](const FapFrame& frame) {
      tape_->record(frame);
      return check(frame);
    });
  }
  // `keep_tape`: the tape stays for verify().
  Status second_pass(const FapFrameSink& code, bool keep_tape) {
    if (!taped()) return read_again(code);
    const FbaInputFrames next = replayed(keep_tape);
    for (std::size_t k = 0; k < frames_read(); ++k)
      if (auto status = code(next()); !status) return status;
    return ok_status();
  }
  // Whether the first pass kept every frame on the tape.
  bool taped() const { return tape_ && !tape_->dropped(); }
  // verify_fba of `encoded` against the frames on the tape (kept through the second pass).
  Status verify(const EncodedFba& encoded, const FbaEncodeOptions& options, int fps, const std::string& file) {
    return verify_fba(frames_read(), fps, replayed(true), encoded, options, file);
  }
  // Whether the first pass already numbers the frames as placed in time.
  virtual bool placed_in_first_pass() const { return false; }
  // Where frame `number` (as placed) was read, for the encoder's errors about one frame
  // (FbaEncodeOptions::locate); nothing known before the first pass is done, or for a stream.
  virtual Location locate(std::int64_t number, int fap) const {
    (void)number, (void)fap;
    return Location{};
  }

 protected:
  virtual Result<SourceFacts> read(const FapFrameSink& check) = 0;
  // The second pass from the file again, frames numbered as placed.
  virtual Status read_again(const FapFrameSink& code) = 0;
  // How many frames the first pass read, and frame k's number as placed in time.
  virtual std::size_t frames_read() const = 0;
  virtual std::int64_t placed(std::size_t k, std::int64_t number) const {
    (void)k;
    return number;
  }

 private:
  // The frames on the tape, numbered as placed: each call the next one.
  FbaInputFrames replayed(bool keep_tape) {
    return [this, replay = tape_->play(keep_tape), frame = FapFrame{},
            k = std::size_t{0}]() mutable -> const FapFrame& {
      frame = replay.next();
      frame.number = placed(k++, frame.number);
      return frame;
    };
  }

  std::optional<FrameTape> tape_;
};

class FapSource : public FrameSource {
 public:
  FapSource(MappedFile file, const std::string& path, const ConvertOptions& options)
      : file_(std::move(file)), path_(path) {
    read_options_.max_frames = options.limits.max_frames;
  }

  Location locate(std::int64_t number, int fap) const override {
    return locator_ ? locator_(number, fap) : Location{};
  }

 protected:
  Result<SourceFacts> read(const FapFrameSink& check) override {
    std::int64_t ordinal = 0;
    auto scan = scan_fap_text(text(), path_, read_options_, [&](const FapFrame& frame) {
      FapFrame in_order = frame;
      in_order.number = ordinal++;
      return check(in_order);
    }, let_go());
    if (!scan) return scan.error();
    numbers_ = std::move(scan->numbers);
    value_lines_ = std::move(scan->read.value_lines);
    locator_ = frame_locator(numbers_, value_lines_, path_);
    const FapReadResult& read = scan->read;
    SourceFacts facts{read.sequence.name, read.sequence.fps, {}, read.warnings, numbers_.size(), 0, 0};
    if (read.facts.has_header) facts.rate_at = read.facts.header_fps_at;
    if (!numbers_.empty()) facts.first_number = numbers_.front(), facts.last_number = numbers_.back();
    return facts;
  }

  Status read_again(const FapFrameSink& code) override {
    std::size_t k = 0;
    auto again = scan_fap_text(text(), path_, read_options_, [&](const FapFrame& read) {
      if (k == numbers_.size()) return Status(changed());
      FapFrame frame = read;
      frame.number = numbers_[k++];
      return code(frame);
    }, let_go());
    if (!again || k != numbers_.size()) return changed();
    return ok_status();
  }
  std::size_t frames_read() const override { return numbers_.size(); }
  std::int64_t placed(std::size_t k, std::int64_t) const override { return numbers_[k]; }

 private:
  std::string_view text() const { return file_.bytes(); }
  std::function<void(std::size_t)> let_go() const {
    return [this](std::size_t offset) { file_.release(offset); };
  }
  Diagnostic changed() const {
    return make_error(ErrorKind::io, Location{path_, 0, 0, -1}, "the file changed while it was read");
  }
  MappedFile file_;
  std::string path_;
  FapReadOptions read_options_;
  std::vector<std::int64_t> numbers_;  // frame k's number as placed in time
  std::vector<int> value_lines_;       // and its value line
  std::function<Location(std::int64_t, int)> locator_;  // over the two, once read
};

// A .fba decoded twice: its frames have their numbers as soon as they are decoded.
class FbaSource : public FrameSource {
 public:
  FbaSource(MappedFile file, const std::string& path, const ConvertOptions& options) : file_(std::move(file)) {
    options_.file = path;
    options_.max_frames = options.limits.max_frames;
    name_ = std::filesystem::path(path).stem().string();
  }

  bool placed_in_first_pass() const override { return true; }

 protected:
  Result<SourceFacts> read(const FapFrameSink& check) override {
    SourceFacts facts;
    auto decoded = decode_fba(bytes(), options_, [&](const FapFrame& frame) {
      if (facts.frames++ == 0) facts.first_number = frame.number;
      facts.last_number = frame.number;
      return check(frame);
    });
    if (!decoded) return decoded.error();
    facts.name = name_;
    facts.fps = decoded->sequence.fps;
    facts.warnings = std::move(decoded->warnings);
    frames_ = facts.frames;
    return facts;
  }

  Status read_again(const FapFrameSink& code) override {
    std::size_t k = 0;
    auto again = decode_fba(bytes(), options_, [&](const FapFrame& frame) {
      ++k;
      return code(frame);
    });
    if (!again || k != frames_)
      return make_error(ErrorKind::io, Location{options_.file, 0, 0, -1}, "the file changed while it was read");
    return ok_status();
  }
  std::size_t frames_read() const override { return frames_; }

 private:
  std::span<const std::uint8_t> bytes() const {
    return {reinterpret_cast<const std::uint8_t*>(file_.bytes().data()), file_.bytes().size()};
  }
  MappedFile file_;
  FbaDecodeOptions options_;
  std::string name_;
  std::size_t frames_ = 0;
};

// One FBA encoding (the .fba's, or the .mp4's with planes aligned to bytes) over both passes.
struct Encoding {
  Encoding(const ConvertOptions& options, bool align_planes, const FrameSource& source)
      : fba_options(options_with(options, align_planes, source)), encoder(fba_options) {}
  static FbaEncodeOptions options_with(const ConvertOptions& options, bool align_planes, const FrameSource& source) {
    FbaEncodeOptions fba = fba_encode_options(options);
    fba.align_planes = align_planes;
    // The encoder's errors about one frame point at its line (as encode_checked's do).
    fba.locate = [&source](std::int64_t number, int fap) { return source.locate(number, fap); };
    return fba;
  }
  bool going() const { return !error; }
  void check(const FapFrame& frame) {
    if (going())
      if (auto status = encoder.check(frame); !status) error = status.error();
  }
  void add(const FapFrame& frame) {
    if (going())
      if (auto status = encoder.add(frame); !status) error = status.error();
  }

  FbaEncodeOptions fba_options;
  FbaEncoder encoder;
  std::optional<Diagnostic> error;  // the first, as encode_checked would give it
  std::optional<EncodedFba> encoded;
};

// The .mp4 of the aligned encoding, through a temporary file.
Status write_mp4_output(const EncodedFba& encoded, int fps, const std::string& path, const std::string& input) {
  auto file = AtomicFile::create(path);
  if (!file) return file.error();
  const Status written = xmt::write_mp4(fba_track_view(encoded, fps), nullptr,
                                        [&](std::span<const std::uint8_t> bytes) {
                                          return file->write({reinterpret_cast<const char*>(bytes.data()), bytes.size()});
                                        });
  if (!written) {
    Diagnostic error = written.error();
    if (error.where.file.empty()) error.where.file = input;
    return error;
  }
  return file->commit();
}

// The result's facts of the first pass, as loading would give them; false (and the error set)
// when the pass failed or --strict refuses the warnings.
bool take_facts(ConvertResult& result, const Result<SourceFacts>& read, const std::bitset<kFapCount>& faps,
                const std::string& input, const ConvertOptions& options) {
  if (!read) {
    result.error = read.error();
    return false;
  }
  const SourceFacts& facts = *read;
  result.warnings = facts.warnings;
  result.loaded.origin = input;
  result.loaded.frames.name = facts.name;
  result.loaded.frames.fps = facts.fps;
  result.loaded.warnings = facts.warnings;
  result.frames = {facts.frames, facts.fps, faps, facts.last_number};
  if (options.strict && !result.warnings.empty()) {
    result.error = strict_error(input, result.warnings.size());
    return false;
  }
  return true;
}

// A decoded .fba to one .fap in a single pass: the frames are written as they are decoded, to an
// unnamed scratch file beside the output, and the output is the header (which needs the frame
// count and rate, known at the end) followed by that text. The frames' text depends only on the
// first frame's number, except in the SEMAINE flavour (times in ms need the rate): that one, and
// a scratch file that cannot be made, take the two passes (empty result).
std::optional<ConvertResult> convert_in_one_pass(FrameSource& source, const std::string& input,
                                                 const std::string& path, const ConvertOptions& options) {
  if (!source.placed_in_first_pass() || options.fap_flavour == FapFlavour::semaine) return std::nullopt;
  auto body = ScratchFile::create(path);
  if (!body) return std::nullopt;
  const FapWriteOptions write_options = fap_write_options(options);
  std::optional<FapTextWriter> writer;  // from the first frame, whose number the text needs
  std::string text;
  std::optional<Diagnostic> fap_error, body_error;
  const auto flush = [&](bool always) {
    if (!always && text.size() < (std::size_t{1} << 20)) return;
    if (!body_error)
      if (auto written = body->write(text); !written) body_error = written.error();
    text.clear();
  };
  std::bitset<kFapCount> faps;
  auto facts = source.first_pass([&](const FapFrame& frame) -> Status {
    faps |= frame.mask;
    if (fap_error) return ok_status();
    if (!writer) writer.emplace(std::string(), 0, 0, frame.number, frame.number, write_options);
    if (auto status = writer->add(frame, text); !status) fap_error = status.error();
    else flush(false);
    return ok_status();
  }, false);
  ConvertResult result;
  if (!take_facts(result, facts, faps, input, options)) return result;
  FapTextWriter header_writer(facts->name, facts->fps, facts->frames, facts->first_number, facts->last_number,
                              write_options);
  std::string header;
  // The header's error (a rate the flavour cannot carry) comes before any frame's, as the usual writer gives them.
  if (auto status = header_writer.begin(header); !status) fap_error = status.error();
  if (writer && !fap_error) writer->finish(text);
  flush(true);
  Status written = ok_status();
  if (fap_error) {
    written = fap_writer_error_at(*fap_error, path);
  } else if (body_error) {
    written = *body_error;
  } else if (auto file = AtomicFile::create(path); !file) {
    written = file.error();
  } else if (written = file->write(header); written) {
    written = body->read_back([&](std::string_view piece) { return file->write(piece); });
    if (written) written = file->commit();
  }
  if (!written) result.error = written.error();
  else result.written.push_back(path);
  return result;
}

std::unique_ptr<FrameSource> open_source(const std::string& input, const ConvertOptions& options) {
  auto mapped = MappedFile::open(input);
  // The usual way reports an unreadable file, inflates a gzip one, and reads one that says it is
  // empty (a file of /proc) as it is.
  if (!mapped || mapped->bytes().empty() || is_gzip(mapped->bytes())) return nullptr;
  if (formats().input_for(input)->kind == "fap") return std::make_unique<FapSource>(std::move(*mapped), input, options);
  return std::make_unique<FbaSource>(std::move(*mapped), input, options);
}

}  // namespace

std::optional<ConvertResult> convert_streamed(const std::string& input, const std::vector<OutputRequest>& outputs,
                                              const std::vector<const OutputFormat*>& writers,
                                              const ConvertOptions& options) {
  if (!can_stream(input, outputs, writers, options)) return std::nullopt;
  std::unique_ptr<FrameSource> source = open_source(input, options);
  if (!source) return std::nullopt;
  if (outputs.size() == 1 && writers[0]->kind == "fap")
    if (auto done = convert_in_one_pass(*source, input, outputs[0].path, options)) return done;
  bool wants_fba = false, wants_mp4 = false;
  for (const OutputFormat* writer : writers) {
    wants_fba = wants_fba || writer->kind == "fba";
    wants_mp4 = wants_mp4 || writer->kind == "mp4";
  }

  // Pass 1. Each encoder checks each frame as it comes; its error, if any, is the one writing
  // its output would give, so it waits until the reading has succeeded (reading errors come
  // first).
  std::optional<Encoding> fba, mp4;
  if (wants_fba) fba.emplace(options, false, *source);
  if (wants_mp4) mp4.emplace(options, true, *source);
  // The frames go on the tape where that pays: a decoded .fba (replaying takes a third of the time
  // of decoding again) and frames for an encoder (as fast as reading the .fap again, and a lower
  // peak: 149 against 165 MB at 10^6 frames). A .fap only rewritten as .fap is read again (the
  // tape would be some 50 bytes a frame more for the same time).
  const bool onto_tape = wants_fba || wants_mp4 || source->placed_in_first_pass();
  std::bitset<kFapCount> faps;
  auto facts = source->first_pass([&](const FapFrame& frame) -> Status {
    faps |= frame.mask;
    if (fba) fba->check(frame);
    if (mp4) mp4->check(frame);
    return ok_status();
  }, onto_tape);
  ConvertResult result;
  if (!take_facts(result, facts, faps, input, options)) return result;
  // --verify compares the stream with the frames on the tape; frames too many for it take the
  // usual way (nothing is written yet).
  if (options.verify && (fba || mp4) && !source->taped()) return std::nullopt;
  // As encode_checked: a rate the stream cannot code comes before any other error of encoding.
  const auto rate_error = fba_rate_error(facts->fps, facts->rate_at, facts->fps, input);
  for (std::optional<Encoding>* encoding : {&fba, &mp4}) {
    if (!*encoding) continue;
    if (rate_error) (*encoding)->error = rate_error;
    if ((*encoding)->going())
      if (auto status = (*encoding)->encoder.start(facts->fps); !status) (*encoding)->error = status.error();
  }

  // Pass 2: the frames again, numbered as placed in time, to the encoders and the .fap text.
  FapTextOutputs fap(facts->name, facts->fps, facts->frames, facts->first_number, facts->last_number, options);
  for (std::size_t i = 0; i < outputs.size(); ++i)
    if (writers[i]->kind == "fap") fap.open(i, outputs[i].path);
  const bool wants_text = fap.any();
  if (wants_text) fap.begin();
  const bool coding = (fba && fba->going()) || (mp4 && mp4->going());
  if (coding || wants_text) {
    const auto code = [&](const FapFrame& frame) -> Status {
      if (fba) fba->add(frame);
      if (mp4) mp4->add(frame);
      if (wants_text) fap.add(frame);
      return ok_status();
    };
    if (auto again = source->second_pass(code, options.verify); !again) {
      result.error = again.error();
      return result;
    }
  }
  if (wants_text) fap.finish();
  for (std::optional<Encoding>* encoding : {&fba, &mp4}) {
    if (!*encoding || !(*encoding)->going()) continue;
    auto finished = (*encoding)->encoder.finish();
    if (finished) (*encoding)->encoded = std::move(*finished);
    else (*encoding)->error = finished.error();
    (*encoding)->encoder = FbaEncoder();  // its statistics of the masks go before the outputs are made
    if (options.verify && finished)  // as encode_checked verifies
      if (auto verified = source->verify(*(*encoding)->encoded, (*encoding)->fba_options, facts->fps, input); !verified)
        (*encoding)->error = verified.error();
  }
  for (std::optional<Encoding>* encoding : {&fba, &mp4})
    if (*encoding && (*encoding)->error && (*encoding)->error->where.file.empty())
      (*encoding)->error->where.file = input;  // as encode_checked names the input

  // The outputs in request order, up to the first that failed (as the usual way writes them).
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    const std::string& path = outputs[i].path;
    Status written = ok_status();
    if (writers[i]->kind == "fba") {
      if (fba->error) written = *fba->error;
      else
        written = write_file_atomic(path, {reinterpret_cast<const char*>(fba->encoded->bytes.data()),
                                           fba->encoded->bytes.size()});
    } else if (writers[i]->kind == "mp4") {
      // As the usual MP4 writer: an empty input would make a track without samples.
      if (facts->frames == 0)
        written = make_error(Location{input, 0, 0, -1}, "no frames to write: an MP4 FBA track needs at least one");
      else if (mp4->error) written = *mp4->error;
      else written = write_mp4_output(*mp4->encoded, facts->fps, path, input);
    } else if (auto failed = fap.error_of(i, path)) {
      written = *failed;
    } else {
      written = fap.commit(i);
    }
    if (!written) {
      result.error = written.error();
      return result;
    }
    result.written.push_back(path);
  }
  return result;
}

}  // namespace fapc::pipeline
