#include "resampler.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace fapc::pipeline::bridges {

void Resampler::emit(std::int64_t frame, const vocabulary::FapVector& values) {
  FapFrame out;
  out.number = frame;
  for (int fap = 3; fap <= kFapCount; ++fap) {
    const auto i = static_cast<std::size_t>(fap - 1);
    if (!faps_.test(i)) continue;
    const double legal = fap_table()[i].legal_max();
    out.set(fap, static_cast<std::int32_t>(std::lround(std::clamp(values[i], -legal, legal))));
  }
  out_.frames.push_back(out);
}

Status Resampler::push(double time, const vocabulary::FapVector& values, const Location& where) {
  if (!started_) {
    started_ = true;
    first_time_ = time;
    previous_time_ = 0;
    previous_ = values;
  }
  const double t = time - first_time_;
  // The frames whose time falls in (previous sample, this sample]; the first sample makes frame 0.
  // Compared as a double first: a time of 1e308 s has no frame number an integer can hold.
  const double frames = std::floor(t * fps_ + 1e-9) + 1;
  if (!(frames <= static_cast<double>(limits_.max_frames))) {
    std::ostringstream what;
    what << "the rows reach " << t << " s, " << frames << " frames at " << fps_ << " fps";
    return limit_error(where, what.str(), Limit::frames, limits_);
  }
  const auto last = static_cast<std::int64_t>(frames) - 1;
  for (; next_frame_ <= last; ++next_frame_) {
    const double at = static_cast<double>(next_frame_) / fps_;
    const double span = t - previous_time_;
    const double share = span > 0 ? std::clamp((at - previous_time_) / span, 0.0, 1.0) : 1.0;
    vocabulary::FapVector mixed{};
    for (std::size_t i = 0; i < mixed.size(); ++i) mixed[i] = previous_[i] + share * (values[i] - previous_[i]);
    emit(next_frame_, mixed);
  }
  previous_time_ = t;
  previous_ = values;
  return ok_status();
}

}  // namespace fapc::pipeline::bridges
