// The viseme track of FAP 1 for lip-sync engines, in the OpenXR / Oculus names.
#include <charconv>

#include "fapc/vocabulary/visemes.hpp"
#include "writers.hpp"

namespace fapc::pipeline::bridges {
namespace {

// A frame's time in seconds, the shortest text that reads back as the same double.
std::string seconds(std::int64_t frame, int fps) {
  char text[32];
  const double value = static_cast<double>(frame) / fps;
  return std::string(text, std::to_chars(text, text + sizeof text, value).ptr);
}

}  // namespace

std::vector<VisemeSpan> viseme_spans(const FapSequence& frames) {
  std::vector<VisemeSpan> spans;
  int shown = 0;  // silence until a frame sends FAP 1
  std::int64_t next = 0;
  const auto extend = [&](std::int64_t end) {
    if (end <= next) return;
    if (!spans.empty() && spans.back().viseme == shown && spans.back().end_frame == next) {
      spans.back().end_frame = end;
    } else {
      spans.push_back({next, end, shown});
    }
    next = end;
  };
  for (const FapFrame& frame : frames.frames) {
    extend(frame.number);  // the frames before this one (a gap) keep the viseme held
    if (frame.has(1)) {
      // viseme_blend / 63 is the first viseme's weight: the one with more shows.
      shown = 2 * frame.viseme.blend >= 63 ? frame.viseme.select1 : frame.viseme.select2;
      if (shown < 0 || shown >= vocabulary::kVisemeCount) shown = 0;
    }
    extend(frame.number + 1);
  }
  return spans;
}

std::string write_viseme_json(const FapSequence& frames) {
  const int fps = frames.fps > 0 ? frames.fps : 25;
  std::string out = "{\n  \"fps\": " + std::to_string(fps) + ",\n  \"visemes\": [";
  const std::vector<VisemeSpan> spans = viseme_spans(frames);
  for (std::size_t i = 0; i < spans.size(); ++i) {
    const VisemeSpan& s = spans[i];
    out += i ? ",\n    " : "\n    ";
    out += "{\"start\": " + seconds(s.first_frame, fps) + ", \"end\": " + seconds(s.end_frame, fps) +
           ", \"viseme\": \"" + std::string(vocabulary::openxr_viseme_name(s.viseme)) +
           "\", \"mpeg4\": " + std::to_string(s.viseme) + "}";
  }
  out += spans.empty() ? "]\n}\n" : "\n  ]\n}\n";
  return out;
}

std::string write_viseme_csv(const FapSequence& frames) {
  const int fps = frames.fps > 0 ? frames.fps : 25;
  std::string out = "start,end,viseme,mpeg4\n";
  for (const VisemeSpan& s : viseme_spans(frames)) {
    out += seconds(s.first_frame, fps) + "," + seconds(s.end_frame, fps) + "," +
           std::string(vocabulary::openxr_viseme_name(s.viseme)) + "," + std::to_string(s.viseme) + "\n";
  }
  return out;
}

}  // namespace fapc::pipeline::bridges
