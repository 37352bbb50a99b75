// What every fuzz target of a reader that yields a timeline checks (FML, XMT-Omega): an error
// names its place in the document (file:line:col), and an accepted document is a sane timeline:
// a finite end, finite clips with begin < end, and finite values at the clips' starts.
#pragma once

#include <cmath>
#include <cstdlib>

#include "fapc/codec/diagnostic.hpp"
#include "fapc/transcoder/render.hpp"

namespace fapc::fuzz {

template <class Read>
int check_timeline_read(const Result<Read>& read) {
  if (!read.ok()) {
    if (read.error().where.line <= 0) std::abort();
    return 0;
  }
  const Timeline& timeline = read->timeline;
  if (!std::isfinite(timeline.end()) || timeline.end() < 0) std::abort();
  const TimelineEvaluator evaluator(timeline);
  std::size_t checked = 0;
  for (const Clip& clip : timeline.clips) {
    if (!(clip.begin < clip.end) || !std::isfinite(clip.begin) || !std::isfinite(clip.end)) std::abort();
    if (checked++ < 64 && !std::isfinite(evaluator.value_at(clip.target, clip.begin))) std::abort();
  }
  return 0;
}

}  // namespace fapc::fuzz
