#include <algorithm>
#include <sstream>

#include "fapc/timeline/timeline.hpp"

namespace fapc::timeline {

double Timeline::end() const {
  if (explicit_end) return *explicit_end;
  double latest = 0;
  for (const Clip& clip : clips) latest = std::max(latest, clip.end);
  return latest;
}

const char* to_string(Interpolation how) {
  switch (how) {
    case Interpolation::linear:
      return "linear";
    case Interpolation::step:
      return "step";
    case Interpolation::sin:
      return "sin";
    case Interpolation::log:
      return "log";
    case Interpolation::exp:
      return "exp";
  }
  return "?";
}

const char* to_string(BlendMode mode) {
  switch (mode) {
    case BlendMode::add:
      return "add";
    case BlendMode::average:
      return "average";
    case BlendMode::overwrite:
      return "overwrite";
  }
  return "?";
}

const char* to_string(Fill fill) { return fill == Fill::freeze ? "freeze" : "remove"; }

std::string dump(const Timeline& timeline) {
  std::ostringstream out;
  out.precision(10);
  out << "timeline end " << timeline.end() << (timeline.explicit_end ? " (explicit)" : "") << '\n';
  for (const Clip& clip : timeline.clips) {
    out << clip.target << " [" << clip.begin << ", " << clip.end << ") " << to_string(clip.blend) << ' '
        << to_string(clip.fill);
    if (clip.curve_offset != 0) out << " offset " << clip.curve_offset;
    if (clip.curve.periodic) {
      const Periodic& p = *clip.curve.periodic;
      out << (p.shape == Periodic::Shape::sine ? " sine" : " triangle") << " min " << p.min << " max " << p.max
          << " period " << p.period;
    } else {
      out << " keys";
      for (const KeyPoint& key : clip.curve.keys) {
        out << ' ' << key.time << ':' << key.value;
        if (&key != &clip.curve.keys.back()) out << ':' << to_string(key.to_next);
      }
    }
    if (!clip.source.file.empty() || clip.source.line > 0) {
      out << " @" << clip.source.file << ':' << clip.source.line << ':' << clip.source.column;
    }
    out << '\n';
  }
  return out.str();
}

}  // namespace fapc::timeline
