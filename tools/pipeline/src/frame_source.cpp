#include "frame_source.hpp"

#include "fapc/pipeline/fba_io.hpp"

namespace fapc::pipeline {

Result<SourceFacts> FrameSource::first_pass(const FapFrameSink& check, bool onto_tape) {
  if (!onto_tape) return read(check);
  tape_.emplace(kFrameTapeBudget);
  auto facts = read([&](const FapFrame& frame) {
    tape_->record(frame);
    return check(frame);
  });
  if (facts && taped()) taped_whole();
  return facts;
}

Status FrameSource::second_pass(const FapFrameSink& code, bool keep_tape) {
  if (!taped()) return read_again(code);
  const FbaInputFrames next = replayed(keep_tape);
  for (std::size_t k = 0; k < frames_read(); ++k)
    if (auto status = code(next()); !status) return status;
  return ok_status();
}

Status FrameSource::verify(const EncodedFba& encoded, const FbaEncodeOptions& options, int fps,
                           const std::string& file) {
  return verify_fba(frames_read(), fps, replayed(true), encoded, options, file);
}

FbaInputFrames FrameSource::replayed(bool keep_tape) {
  return [this, replay = tape_->play(keep_tape), frame = FapFrame{}, k = std::size_t{0}]() mutable -> const FapFrame& {
    frame = replay.next();
    frame.number = placed(k++, frame.number);
    return frame;
  };
}

}  // namespace fapc::pipeline
