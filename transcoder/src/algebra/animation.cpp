// The operators on animations (Algebra definitions 4 to 6, docs/algebra.md, "Animations").
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "fapc/codec/fap_table.hpp"
#include "fapc/transcoder/algebra.hpp"

namespace fapc::algebra {
namespace {

// `a` on the grid of `fps`: itself when it is there already (no copy: a chain of operators would
// otherwise copy every operand once more), else resampled into `store`.
const Animation& on_grid(const Animation& a, int fps, Animation& store) {
  if (a.fps == fps) return a;
  store = resample(a, fps);
  return store;
}

// Both operands on the higher frame rate; past the end of the shorter one, only the longer.
template <class BothFn>
Animation frame_by_frame(const Animation& a, const Animation& b, BothFn both) {
  const int fps = std::max(a.fps, b.fps);
  Animation a_store, b_store;
  const Animation& x = on_grid(a, fps, a_store);
  const Animation& y = on_grid(b, fps, b_store);
  Animation out;
  out.fps = fps;
  out.carried = a.carried | b.carried;
  out.frames.resize(std::max(x.size(), y.size()));
  static const std::optional<FacialState> none;
  for (std::size_t k = 0; k < out.size(); ++k) {
    const auto& s = k < x.size() ? x.frames[k] : none;
    const auto& t = k < y.size() ? y.frames[k] : none;
    out.frames[k] = s && t ? both(*s, *t) : s ? *s : t ? *t : FacialState{};
  }
  return out;
}

}  // namespace

Animation animation_from(const FapSequence& sequence) {
  Animation a;
  a.fps = sequence.fps;
  if (sequence.frames.empty()) return a;
  a.frames.resize(static_cast<std::size_t>(sequence.frames.back().number + 1));
  for (const FapFrame& frame : sequence.frames) {
    if (frame.number < 0) continue;
    FacialState state;
    for (int fap = 3; fap <= kFapCount; ++fap) {
      if (!frame.has(fap)) continue;
      state.at(fap) = frame.value(fap);
      a.carried.set(static_cast<std::size_t>(fap - 3));
    }
    a.frames[static_cast<std::size_t>(frame.number)] = state;
  }
  return a;
}

FapSequence sequence_from(const Animation& a, const std::string& name) {
  FapSequence out;
  out.name = name;
  out.fps = a.fps;
  for (std::size_t k = 0; k < a.size(); ++k) {
    if (!a.frames[k]) continue;
    FapFrame frame;
    frame.number = static_cast<std::int64_t>(k);
    for (int fap = 3; fap <= kFapCount; ++fap) {
      const std::int32_t v = a.frames[k]->at(fap);
      if (v != 0 || a.carried.test(static_cast<std::size_t>(fap - 3))) frame.set(fap, v);
    }
    out.frames.push_back(frame);
  }
  return out;
}

Animation resample(const Animation& a, int fps) {
  if (fps == a.fps || a.frames.empty()) {
    Animation same = a;
    same.fps = fps;
    return same;
  }
  Animation out;
  out.fps = fps;
  out.carried = a.carried;
  const double ratio = static_cast<double>(a.fps) / fps;
  const auto size = static_cast<std::size_t>(std::ceil(static_cast<double>(a.size()) / ratio - 1e-9));
  out.frames.resize(size);
  for (std::size_t j = 0; j < size; ++j) {
    const double x = static_cast<double>(j) * ratio;
    const auto i = static_cast<std::size_t>(std::floor(x + 1e-9));
    const double u = x - static_cast<double>(i);
    if (i >= a.size() || !a.frames[i]) continue;
    if (u < 1e-9 || i + 1 >= a.size() || !a.frames[i + 1]) {
      out.frames[j] = a.frames[i];  // on a frame, or after the last one of a run: hold it
      continue;
    }
    FacialState mixed;
    for (std::size_t f = 0; f < mixed.values.size(); ++f) {
      mixed.values[f] = round_half_away(a.frames[i]->values[f] * (1 - u) + a.frames[i + 1]->values[f] * u);
    }
    out.frames[j] = mixed;
  }
  return out;
}

Animation shifted(const Animation& a, double seconds) {
  Animation out = a;
  const long frames = std::lround(seconds * a.fps);
  if (frames >= 0) {
    out.frames.insert(out.frames.begin(), static_cast<std::size_t>(frames), std::nullopt);
  } else {
    const auto drop = std::min(out.frames.size(), static_cast<std::size_t>(-frames));
    out.frames.erase(out.frames.begin(), out.frames.begin() + static_cast<std::ptrdiff_t>(drop));
  }
  return out;
}

void delay_in_place(Animation& a, long frames) {
  if (frames > 0) a.frames.insert(a.frames.begin(), static_cast<std::size_t>(frames), std::nullopt);
}

Animation sum(const Animation& a, const Animation& b, double v) {
  return frame_by_frame(a, b, [v](const FacialState& s, const FacialState& t) { return sum(s, t, v); });
}

Animation amplify(const Animation& a, double w) {
  Animation out = a;
  for (auto& frame : out.frames) {
    if (frame) *frame = amplify(*frame, w);
  }
  return out;
}

Result<Animation> overlap(const std::vector<LayeredAnimation>& operands) {
  Animation out;
  if (operands.empty()) return out;
  for (const LayeredAnimation& o : operands) out.fps = std::max(out.fps, o.animation.fps);
  std::vector<Animation> grids;
  std::size_t size = 0;
  for (const LayeredAnimation& o : operands) {
    grids.push_back(resample(o.animation, out.fps));
    size = std::max(size, grids.back().size());
    out.carried |= o.animation.carried & o.mask.bits;
  }
  out.frames.resize(size);
  for (std::size_t k = 0; k < size; ++k) {
    std::optional<Layer> folded;
    for (std::size_t n = 0; n < operands.size(); ++n) {
      if (k >= grids[n].size() || !grids[n].frames[k]) continue;
      const Layer layer = Layer::of(*grids[n].frames[k], operands[n].mask, operands[n].priority);
      if (!folded) {
        folded = layer;
        continue;
      }
      Result<Layer> next = overlap(*folded, layer);
      if (!next) {
        Diagnostic d = next.error();
        char at[48];
        std::snprintf(at, sizeof at, " (at %g s)", static_cast<double>(k) / out.fps);
        d.message += at;
        return d;
      }
      folded = *next;
    }
    out.frames[k] = folded ? folded->state : FacialState{};
  }
  return out;
}

}  // namespace fapc::algebra
