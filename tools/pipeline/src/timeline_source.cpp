// A script's frames one at a time (frame_source.hpp): the front end lowers it to its timeline as
// usual (no frames, no curves), then FrameStream renders frame k on demand. Rendering is
// deterministic, so a second pass without the tape renders the same frames again; once the tape
// holds them all, the timeline and its index go (their memory goes to the encoder's planes).
#include <algorithm>

#include "frame_source.hpp"
#include "timeline_input.hpp"

namespace fapc::pipeline {

namespace {

class TimelineSource : public FrameSource {
 public:
  // The lowered script: its timeline and the front end's warnings.
  static Result<std::unique_ptr<FrameSource>> open(Loaded lowered, const std::string& input,
                                                   const ConvertOptions& options) {
    auto source = std::make_unique<TimelineSource>();
    source->timeline_ = std::make_unique<Timeline>(std::move(*lowered.timeline));
    source->warnings_ = std::move(lowered.warnings);
    Result<Profile> profile = profile_for(options);
    if (!profile) return profile.error();
    source->profile_.emplace(std::move(*profile));
    Result<FrameStream> started = stream_frames(*source->timeline_, input, *source->profile_, options);
    if (!started) return started.error();
    source->stream_.emplace(std::move(*started));
    if (auto audio = mixed_audio(*source->timeline_, options); !audio) return audio.error();
    const FrameStream& stream = *source->stream_;
    source->count_ = stream.count();
    source->facts_.name = stream.name();
    source->facts_.fps = stream.fps();
    source->facts_.frames = static_cast<std::size_t>(stream.count());
    source->facts_.last_number = std::max<std::int64_t>(stream.count() - 1, 0);
    source->facts_.numbered_from_zero = true;
    return std::unique_ptr<FrameSource>(std::move(source));
  }

  std::optional<SourceFacts> facts_up_front() const override { return facts_; }
  bool placed_in_first_pass() const override { return true; }

 protected:
  Result<SourceFacts> read(const FapFrameSink& check) override {
    for (std::int64_t k = 0; k < count_; ++k)
      if (auto status = check(stream_->frame(k)); !status) return status.error();
    SourceFacts facts = facts_;
    facts.warnings = warnings_;  // the front end's, then rendering's
    facts.warnings.insert(facts.warnings.end(), stream_->warnings().begin(), stream_->warnings().end());
    return facts;
  }
  Status read_again(const FapFrameSink& code) override {
    for (std::int64_t k = 0; k < count_; ++k)
      if (auto status = code(stream_->frame(k)); !status) return status;
    return ok_status();
  }
  std::size_t frames_read() const override { return static_cast<std::size_t>(count_); }
  void taped_whole() override {
    stream_.reset();
    timeline_.reset();
  }

 private:
  std::unique_ptr<Timeline> timeline_;
  std::optional<Profile> profile_;     // the stream's, which refers to it
  std::optional<FrameStream> stream_;  // over the timeline
  Diagnostics warnings_;               // the front end's
  SourceFacts facts_;
  std::int64_t count_ = 0;
};

}  // namespace

Result<std::unique_ptr<FrameSource>> open_timeline_source(const std::string& input, const ConvertOptions& options) {
  // The front end alone: the timeline, its warnings, no frames and no curves.
  ConvertOptions lower_only = options;
  lower_only.render = false;
  lower_only.renders_later = true;
  lower_only.curves = false;
  Result<Loaded> lowered = load(input, lower_only);
  if (!lowered) return lowered.error();
  if (!lowered->timeline) return std::unique_ptr<FrameSource>();  // not reached: a script's load keeps its timeline
  return TimelineSource::open(std::move(*lowered), input, options);
}

}  // namespace fapc::pipeline
