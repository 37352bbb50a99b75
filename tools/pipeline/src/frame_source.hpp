// The one engine's two ends (docs/architecture.md, "One engine"): a FrameSource gives an input's
// frames one at a time, a FrameWriter takes them for one output. Readers and writers offer them in
// their rows (InputFormat::frames and ::timeline, OutputFormat::frame_writer); convert() streams
// when every requested writer has one (streamed_convert.cpp). Private to the pipeline.
//
// The frames may be needed twice: the FBA encoder checks every frame and plans its masks over the
// whole sequence before it codes the first, the .fap header holds the frame count, and what a
// .fap file's numbers mean is known only at its end. The first pass may keep the frames on a
// compact tape (frame_tape.hpp) that the second replays; a tape past its budget is dropped and the
// second pass reads (or renders) the input again.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "fapc/codec/fap_file.hpp"
#include "fapc/codec/fba.hpp"
#include "fapc/pipeline/registry.hpp"
#include "frame_tape.hpp"

namespace fapc::pipeline {

// What a source's frames are, as loading would have given it.
struct SourceFacts {
  std::string name;  // the sequence's name (the .fap header's, the file's stem, the script's)
  int fps = 25;
  Location rate_at;  // where the input wrote the rate, if it did
  Diagnostics warnings;
  std::size_t frames = 0;
  std::int64_t first_number = 0, last_number = 0;  // as placed in time
  bool numbered_from_zero = false;  // frames 0 .. frames - 1 (a rendered timeline): the summary says no last number
};

class FrameSource {
 public:
  virtual ~FrameSource() = default;

  // The facts before any frame is read, when the source knows them (a timeline knows its name,
  // rate and length): writers that need them first (the .fap header) can then write in one pass.
  virtual std::optional<SourceFacts> facts_up_front() const { return std::nullopt; }
  // The first pass: every frame to `check`, numbered so that the encoder's checks of numbers hold
  // (a .fap's numbers mean something only once it is all read: its reader checks them itself).
  // `onto_tape`: the frames are kept for the second pass (within the tape's budget). Reading
  // errors come from here.
  Result<SourceFacts> first_pass(const FapFrameSink& check, bool onto_tape);
  // The second pass: the frames again, numbered as placed in time. `keep_tape`: for verify().
  Status second_pass(const FapFrameSink& code, bool keep_tape);
  // Whether the first pass kept every frame on the tape.
  bool taped() const { return tape_ && !tape_->dropped(); }
  // verify_fba of `encoded` against the frames on the tape (kept through the second pass).
  Status verify(const EncodedFba& encoded, const FbaEncodeOptions& options, int fps, const std::string& file);
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
  // The second pass from the input again, frames numbered as placed.
  virtual Status read_again(const FapFrameSink& code) = 0;
  // How many frames the first pass read, and frame k's number as placed in time.
  virtual std::size_t frames_read() const = 0;
  virtual std::int64_t placed(std::size_t k, std::int64_t number) const {
    (void)k;
    return number;
  }
  // The tape holds every frame: what only reading again would need may go (a script's timeline).
  virtual void taped_whole() {}

 private:
  // The frames on the tape, numbered as placed: each call the next one.
  FbaInputFrames replayed(bool keep_tape);

  std::optional<FrameTape> tape_;
};

// One output written from frames one at a time. The engine calls, in order: check() on every frame
// of the first pass when checks_first(); start() once the facts are known (before the pass that
// writes, or after the one pass when start_early() said yes); add() on every frame of the writing
// pass; finish(); and commit() for the outputs in request order, up to the first that fails.
class FrameWriter {
 public:
  virtual ~FrameWriter() = default;
  // Whether it must see every frame before it writes one (the FBA encoder plans its masks over
  // the whole sequence): the frames are then taken twice.
  virtual bool checks_first() const { return false; }
  // Whether it can write the frames as they come, before the facts are known (the .fap body to a
  // scratch file, its header after); false: it needs the facts first. When every writer can, the
  // engine calls start_early() before the one pass, and start() after it.
  virtual bool writes_before_facts() const { return false; }
  virtual void start_early() {}
  virtual void check(const FapFrame& frame) { (void)frame; }
  virtual void start(const SourceFacts& facts) = 0;
  // Whether it wants the writing pass (false once it has failed for good).
  virtual bool wants_frames() const { return true; }
  virtual void add(const FapFrame& frame) = 0;
  virtual void finish() = 0;
  // The output in place, or the error writing it meets (as the writer of the loaded way gives it).
  virtual Status commit() = 0;
};

// A script's source: the front end lowers `input` to its timeline, which is then rendered frame by
// frame (timeline_source.cpp). Errors are the load's.
Result<std::unique_ptr<FrameSource>> open_timeline_source(const std::string& input, const ConvertOptions& options);

}  // namespace fapc::pipeline
