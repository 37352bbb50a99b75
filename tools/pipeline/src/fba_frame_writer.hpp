// An FBA encoding fed one frame at a time by the one engine (frame_source.hpp): the .fba writer's,
// and the .mp4 writer's with its planes aligned to bytes. The encoder checks every frame in the
// first pass (planning its masks over the whole sequence) and codes them in the second. Its errors
// are those of encode_checked, in the same order. Private to the pipeline.
#pragma once

#include <optional>
#include <string>

#include "fapc/codec/fba.hpp"
#include "frame_source.hpp"

namespace fapc::pipeline {

class FbaFrameWriter : public FrameWriter {
 public:
  FbaFrameWriter(const std::string& path, const std::string& input, const ConvertOptions& options, FrameSource& source,
                 bool align_planes);

  bool checks_first() const override { return true; }
  void check(const FapFrame& frame) override;
  void start(const SourceFacts& facts) override;
  bool wants_frames() const override { return !error_; }
  void add(const FapFrame& frame) override;
  void finish() override;
  // The .fba's bytes.
  Status commit() override;

 protected:
  std::string path_, input_;
  SourceFacts facts_;
  std::optional<Diagnostic> error_;  // the first, as encode_checked would give it
  std::optional<EncodedFba> encoded_;

 private:
  bool verify_;
  FrameSource& source_;
  FbaEncodeOptions fba_options_;
  FbaEncoder encoder_;
};

}  // namespace fapc::pipeline
