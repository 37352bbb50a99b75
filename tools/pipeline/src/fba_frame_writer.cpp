#include "fba_frame_writer.hpp"

#include "fapc/codec/file_io.hpp"
#include "fapc/pipeline/fba_io.hpp"

namespace fapc::pipeline {

namespace {

FbaEncodeOptions options_with(const ConvertOptions& options, bool align_planes, const FrameSource& source) {
  FbaEncodeOptions fba = fba_encode_options(options);
  fba.align_planes = align_planes;
  // The encoder's errors about one frame point at its line (as encode_checked's do).
  fba.locate = [&source](std::int64_t number, int fap) { return source.locate(number, fap); };
  return fba;
}

}  // namespace

FbaFrameWriter::FbaFrameWriter(const std::string& path, const std::string& input, const ConvertOptions& options,
                               FrameSource& source, bool align_planes)
    : path_(path),
      input_(input),
      verify_(options.verify),
      source_(source),
      fba_options_(options_with(options, align_planes, source)),
      encoder_(fba_options_) {}

void FbaFrameWriter::check(const FapFrame& frame) {
  if (!error_)
    if (auto status = encoder_.check(frame); !status) error_ = status.error();
}

void FbaFrameWriter::start(const SourceFacts& facts) {
  facts_ = facts;
  facts_.warnings.clear();
  // As encode_checked: a rate the stream cannot code comes before any other error of encoding.
  if (auto rate_error = fba_rate_error(facts.fps, facts.rate_at, facts.fps, input_)) error_ = rate_error;
  if (!error_)
    if (auto status = encoder_.start(facts.fps); !status) error_ = status.error();
}

void FbaFrameWriter::add(const FapFrame& frame) {
  if (!error_)
    if (auto status = encoder_.add(frame); !status) error_ = status.error();
}

void FbaFrameWriter::finish() {
  if (!error_) {
    auto finished = encoder_.finish();
    if (finished)
      encoded_ = std::move(*finished);
    else
      error_ = finished.error();
    encoder_ = FbaEncoder();  // its statistics of the masks go before the outputs are made
    if (verify_ && finished)  // as encode_checked verifies
      if (auto verified = source_.verify(*encoded_, fba_options_, facts_.fps, input_); !verified)
        error_ = verified.error();
  }
  if (error_ && error_->where.file.empty()) error_->where.file = input_;  // as encode_checked names the input
}

Status FbaFrameWriter::commit() {
  if (error_) return *error_;
  return write_file_atomic(path_, {reinterpret_cast<const char*>(encoded_->bytes.data()), encoded_->bytes.size()});
}

}  // namespace fapc::pipeline
