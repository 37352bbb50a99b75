#include "fapc/timeline/timeline_from_frames.hpp"

#include <cmath>
#include <map>
#include <string>

namespace fapc::timeline {
namespace {

// A clip being grown frame by frame.
struct OpenClip {
  std::int64_t first = 0;
  std::int64_t last = 0;
  Clip clip;
};

class Builder {
 public:
  Builder(const FapSequence& sequence, double shift, const Location& source)
      : fps_(sequence.fps), shift_(shift), source_(source) {}

  void add(const std::string& target, std::int64_t frame, double value, Interpolation how) {
    auto found = open_.find(target);
    if (found != open_.end() && found->second.last + 1 != frame) {
      close(found->second);
      open_.erase(found);
      found = open_.end();
    }
    if (found == open_.end()) {
      OpenClip fresh{frame, frame, Clip{}};
      fresh.clip.target = target;
      fresh.clip.begin = shift_ + static_cast<double>(frame) / fps_;
      fresh.clip.source = source_;
      found = open_.emplace(target, std::move(fresh)).first;
    }
    OpenClip& open = found->second;
    open.last = frame;
    std::vector<KeyPoint>& keys = open.clip.curve.keys;
    const double time = static_cast<double>(frame - open.first) / fps_;
    if (how == Interpolation::step) {
      if (keys.empty() || keys.back().value != value) keys.push_back(KeyPoint{time, value, how});
      return;
    }
    // A key on the line through the two before it is not needed (exact: integer frame offsets).
    const std::size_t n = keys.size();
    const auto offset_of = [&](const KeyPoint& key) { return std::llround(key.time * fps_); };
    const auto collinear = [&] {
      const double f0 = static_cast<double>(offset_of(keys[n - 2]));
      const double f1 = static_cast<double>(offset_of(keys[n - 1]));
      const double f2 = static_cast<double>(frame - open.first);
      return (keys[n - 1].value - keys[n - 2].value) * (f2 - f1) == (value - keys[n - 1].value) * (f1 - f0);
    };
    if (n >= 2 && collinear()) {
      keys.back() = KeyPoint{time, value, how};
    } else {
      keys.push_back(KeyPoint{time, value, how});
    }
  }

  // Targets not carried by `frame` end their runs.
  void end_missing(std::int64_t frame) {
    for (auto it = open_.begin(); it != open_.end();) {
      if (it->second.last != frame) {
        close(it->second);
        it = open_.erase(it);
      } else {
        ++it;
      }
    }
  }

  Timeline finish() {
    for (auto& [target, open] : open_) close(open);
    return std::move(timeline_);
  }

 private:
  int fps_;
  double shift_;
  Location source_;
  std::map<std::string, OpenClip> open_;
  Timeline timeline_;

  void close(OpenClip& open) {
    open.clip.end = shift_ + static_cast<double>(open.last + 1) / fps_;
    timeline_.clips.push_back(std::move(open.clip));
  }
};

std::string weight_name(const char* prefix, std::string_view name) { return std::string(prefix) + std::string(name); }

}  // namespace

Timeline timeline_from_frames(const FapSequence& sequence, double shift, const Location& source) {
  Builder builder(sequence, shift, source);
  for (const FapFrame& frame : sequence.frames) {
    for (int fap = 3; fap <= kFapCount; ++fap) {
      if (!frame.has(fap)) continue;
      builder.add(std::string(find_fap(fap)->name), frame.number, frame.value(fap), Interpolation::linear);
    }
    if (frame.has(1)) {
      // blend weighs select1 against select2 (docs/timeline.md); both become weights.
      const VisemeFields& v = frame.viseme;
      builder.add(weight_name("viseme.", viseme_name(v.select1)), frame.number, v.blend, Interpolation::step);
      if (v.select2 != 0 && v.select2 != v.select1) {
        builder.add(weight_name("viseme.", viseme_name(v.select2)), frame.number, 63 - v.blend, Interpolation::step);
      }
    }
    if (frame.has(2)) {
      const ExpressionFields& e = frame.expression;
      builder.add(weight_name("expression.", expression_name(e.select1)), frame.number, e.intensity1,
                  Interpolation::step);
      if (e.select2 != 0 && e.select2 != e.select1) {
        builder.add(weight_name("expression.", expression_name(e.select2)), frame.number, e.intensity2,
                    Interpolation::step);
      }
    }
    builder.end_missing(frame.number);
  }
  Timeline timeline = builder.finish();
  timeline.explicit_end = shift + sequence.duration_seconds();
  return timeline;
}

}  // namespace fapc::timeline
