// .fap and .fap.gz, in and out; the frames read one at a time from a mapped file, and written so.
#include <optional>

#include "../frame_source.hpp"
#include "fap_text_outputs.hpp"
#include "fapc/codec/fap_file.hpp"
#include "fapc/codec/file_io.hpp"
#include "fapc/pipeline/codes.hpp"
#include "fapc/pipeline/fba_io.hpp"
#include "fapc/pipeline/json_access.hpp"
#include "fapc/pipeline/registry.hpp"

namespace fapc::pipeline::builtin {

namespace {

nlohmann::ordered_json facts_of(const FapFileFacts& facts) {
  nlohmann::ordered_json out;
  out["variant"] = facts.variant();
  if (facts.has_header) {
    out["version"] = facts.version;
    out["header_name"] = facts.header_name;
    out["header_frame_count"] = facts.header_count;
  }
  out["deviations"] = facts.deviations();
  return out;
}

Result<Loaded> load_fap(const std::string& path, const ConvertOptions& options) {
  // Mapped, not copied: the text is read once, and its pages are let go behind the reader (the
  // frames are what is kept). A gzip file is inflated whole; an empty one (or one of /proc, which
  // says it is empty) is read the usual way.
  auto mapped = MappedFile::open(path);
  if (!mapped) return mapped.error();
  std::optional<std::string> bytes;
  if (mapped->bytes().empty() || is_gzip(mapped->bytes())) {
    auto read = read_file_bytes(path, options.limits);
    if (!read) return read.error();
    bytes = std::move(*read);
  }
  const std::string_view text = bytes ? std::string_view(*bytes) : mapped->bytes();
  FapReadOptions read_options;
  read_options.max_frames = options.limits.max_frames;
  const auto let_go = [&](std::size_t offset) {
    if (!bytes) mapped->release(offset);
  };
  auto read = read_fap_text(text, path, read_options, let_go);
  if (!read) return read.error();
  Loaded loaded;
  loaded.frames = std::move(read->sequence);
  if (read->facts.has_header) {
    loaded.rate_at = read->facts.header_fps_at;
    loaded.rate_written = loaded.frames.fps;
  }
  loaded.frame_lines = std::move(read->value_lines);
  loaded.warnings = std::move(read->warnings);
  if (options.facts) loaded.facts = json_value(facts_of(read->facts));
  return loaded;
}

Result<std::string> write_fap(const Loaded& loaded, const std::string& path, const ConvertOptions& options) {
  auto text = write_fap_flavour(loaded.frames, fap_write_options(options));
  if (!text) return fap_writer_error_at(text.error(), path);
  return text;
}

// A .fap read from its mapping, twice when the second pass cannot replay the tape. The first pass
// numbers the frames in order (their numbers mean something only once the file is read); the
// second places them in time.
class FapSource : public FrameSource {
 public:
  FapSource(MappedFile file, const std::string& path, const ConvertOptions& options)
      : file_(std::move(file)), path_(path) {
    read_options_.max_frames = options.limits.max_frames;
  }

  Location locate(std::int64_t number, int fap) const override { return locator_ ? locator_(number, fap) : Location{}; }

 protected:
  Result<SourceFacts> read(const FapFrameSink& check) override {
    std::int64_t ordinal = 0;
    auto scan = scan_fap_text(
        text(), path_, read_options_,
        [&](const FapFrame& frame) {
          FapFrame in_order = frame;
          in_order.number = ordinal++;
          return check(in_order);
        },
        let_go());
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
    auto again = scan_fap_text(
        text(), path_, read_options_,
        [&](const FapFrame& read) {
          if (k == numbers_.size()) return Status(changed());
          FapFrame frame = read;
          frame.number = numbers_[k++];
          return code(frame);
        },
        let_go());
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
    return make_error(codes::input::changed_while_read, Location::whole_file(path_),
                      "the file changed while it was read");
  }
  MappedFile file_;
  std::string path_;
  FapReadOptions read_options_;
  std::vector<std::int64_t> numbers_;                   // frame k's number as placed in time
  std::vector<int> value_lines_;                        // and its value line
  std::function<Location(std::int64_t, int)> locator_;  // over the two, once read
};

// The .fap text of frames one at a time, to a temporary file renamed over the output at commit.
// The header comes first, so the facts are needed before the frames; except from a source that
// numbers its frames in its first pass (a decoded .fba), in any flavour but SEMAINE's (its times in
// ms need the rate): then the frames' text (which depends only on the first frame's number) goes
// to an unnamed scratch file as the frames come, and the header before it at the end: one pass.
class FapFrameWriter : public FrameWriter {
 public:
  FapFrameWriter(const std::string& path, const ConvertOptions& options, const FrameSource& source)
      : path_(path),
        options_(options),
        write_options_(fap_write_options(options)),
        early_possible_(source.placed_in_first_pass() && options.fap_flavour != FapFlavour::semaine) {}

  bool writes_before_facts() const override { return early_possible_; }
  void start_early() override {
    early_ = true;
    if (auto body = ScratchFile::create(path_))
      body_.emplace(std::move(*body));
    else
      body_error_ = body.error();  // what creating the output itself says, found at the end
  }

  void start(const SourceFacts& facts) override {
    if (early_) {
      // The header's error (a rate the flavour cannot carry) comes before any frame's, as the
      // usual writer gives them.
      FapTextWriter header_writer(facts.name, facts.fps, facts.frames, facts.first_number, facts.last_number,
                                  write_options_);
      if (auto status = header_writer.begin(header_); !status) text_error_ = status.error();
      return;
    }
    text_.emplace(facts.name, facts.fps, facts.frames, facts.first_number, facts.last_number, options_);
    text_->open(0, path_);
    text_->begin();
  }

  void add(const FapFrame& frame) override {
    if (!early_) return text_->add(frame);
    if (text_error_) return;
    if (!body_writer_) body_writer_.emplace(std::string(), 0, 0, frame.number, frame.number, write_options_);
    if (auto status = body_writer_->add(frame, body_text_); !status)
      text_error_ = status.error();
    else if (body_text_.size() >= (std::size_t{1} << 20))
      flush();
  }

  void finish() override {
    if (!early_) return text_->finish();
    if (body_writer_ && !text_error_) body_writer_->finish(body_text_);
    flush();
  }

  Status commit() override {
    if (!early_) {
      if (auto failed = text_->error_of(0, path_)) return *failed;
      return text_->commit(0);
    }
    if (text_error_) return fap_writer_error_at(*text_error_, path_);
    if (body_error_) return *body_error_;
    auto file = AtomicFile::create(path_);
    if (!file) return file.error();
    if (auto written = file->write(header_); !written) return written;
    if (auto written = body_->read_back([&](std::string_view piece) { return file->write(piece); }); !written)
      return written;
    return file->commit();
  }

 private:
  void flush() {
    if (!body_error_)
      if (auto written = body_->write(body_text_); !written) body_error_ = written.error();
    body_text_.clear();
  }

  std::string path_;
  ConvertOptions options_;
  FapWriteOptions write_options_;
  bool early_possible_;
  bool early_ = false;
  std::optional<FapTextOutputs> text_;  // header first
  // Written early: the frames' text (from the first frame, whose number it needs) and the header.
  std::optional<FapTextWriter> body_writer_;
  std::string body_text_, header_;
  std::optional<ScratchFile> body_;
  std::optional<Diagnostic> text_error_, body_error_;
};

}  // namespace

InputFormat fap_input() {
  InputFormat format{"fap", {".fap", ".fap.gz", ".FAP"}, load_fap};
  format.frames = [](MappedFile file, const std::string& path, const ConvertOptions& options) {
    return std::unique_ptr<FrameSource>(std::make_unique<FapSource>(std::move(file), path, options));
  };
  return format;
}

OutputFormat fap_output() {
  OutputFormat format{"fap", {".fap", ".fap.gz"}, write_fap};
  format.frame_writer = [](const std::string& path, const std::string&, const ConvertOptions& options,
                           FrameSource& source) {
    return std::unique_ptr<FrameWriter>(std::make_unique<FapFrameWriter>(path, options, source));
  };
  return format;
}

}  // namespace fapc::pipeline::builtin
