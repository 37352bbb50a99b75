// Frames from the timeline (docs/timeline.md, "Rendering"): sample, sum the targets that drive each
// FAP, round halves away from zero, clamp to the legal range with one warning per clip.
#include <algorithm>
#include <cmath>
#include <set>
#include <span>
#include <sstream>

#include "fapc/transcoder/codes.hpp"
#include "fapc/transcoder/frame_budget.hpp"
#include "timeline_index.hpp"

namespace fapc {
namespace {

struct Driver {
  const TargetIndex* index;
  std::vector<FapContribution> contributions;
  int weight_slot = -1;    // viseme or expression number for viseme.X / expression.X targets
  std::size_t cursor = 0;  // the elementary interval of the last frame: frames mostly come in order
};

// The two strongest weights become FAP 1 / FAP 2's two slots (ties: the lower number).
std::pair<std::pair<int, int>, std::pair<int, int>> strongest_two(std::span<const int> weights) {
  std::pair<int, int> first{0, 0};
  std::pair<int, int> second{0, 0};
  for (int slot = 1; slot < static_cast<int>(weights.size()); ++slot) {
    const int w = weights[static_cast<std::size_t>(slot)];
    if (w > first.second) {
      second = first;
      first = {slot, w};
    } else if (w > second.second) {
      second = {slot, w};
    }
  }
  return {first, second};
}

class FrameRenderer {
 public:
  FrameRenderer(const Timeline& timeline, const RenderOptions& options) : index_(timeline.clips), options_(options) {}
  FrameRenderer(const FrameRenderer&) = delete;

  // What drives each FAP, per target; an error for a target the profile does not map.
  Status resolve() {
    const Profile& profile = options_.profile ? *options_.profile : default_profile();
    for (const auto& [target, target_index] : index_.targets) {
      Driver driver{&target_index, resolve_target(target, profile), -1};
      if (driver.contributions.empty()) {
        const Clip& first = index_.clips[target_index.clips.front()];
        return make_error(codes::profile::unknown_parameter, first.source, unknown_parameter_message(target, profile));
      }
      if (const std::optional<WeightTarget> weight = weight_target(target)) {
        driver.weight_slot = weight->number;
      }
      drivers_.push_back(std::move(driver));
    }
    return ok_status();
  }

  const RenderOptions& options() const { return options_; }
  const Diagnostics& warnings() const { return warnings_; }
  FapFrame frame_at(std::int64_t k) { return frame_at(drivers_, k); }

 private:
  TimelineIndex index_;
  RenderOptions options_;
  std::vector<Driver> drivers_;
  Diagnostics warnings_;
  std::set<std::int64_t> warned_clips_;

  FapFrame frame_at(std::vector<Driver>& drivers, std::int64_t k) {
    const double t = static_cast<double>(k) / options_.fps;
    FapFrame frame;
    frame.number = k;
    std::array<double, kFapCount> sums{};
    std::array<std::int64_t, kFapCount> causes;
    causes.fill(-1);
    std::array<int, 15> visemes{};
    std::array<int, 7> expressions{};
    for (Driver& driver : drivers) {
      if (t < driver.index->span_begin || t >= driver.index->span_end) continue;
      const Blended blended = index_.value_at(*driver.index, t, false, driver.cursor);
      for (const FapContribution& c : driver.contributions) {
        const auto slot = static_cast<std::size_t>(c.fap - 1);
        frame.mask.set(slot);
        if (driver.weight_slot >= 0) {
          const std::span<int> weights = c.fap == 1 ? std::span<int>(visemes) : std::span<int>(expressions);
          weights[static_cast<std::size_t>(driver.weight_slot)] =
              clamp_and_warn(blended.value, 63, 0, blended.cause, t, "the weight");
          continue;
        }
        sums[slot] += blended.value * c.scale;
        if (blended.cause >= 0 && (causes[slot] < 0 || c.scale != 0)) causes[slot] = blended.cause;
      }
    }
    for (int fap = 3; fap <= kFapCount; ++fap) {
      const auto slot = static_cast<std::size_t>(fap - 1);
      if (!frame.mask.test(slot)) continue;
      const int limit = find_fap(fap)->legal_max();
      frame.values[slot] = clamp_and_warn(sums[slot], limit, -limit, causes[slot], t, find_fap(fap)->name);
    }
    if (frame.has(1)) {
      const auto [a, b] = strongest_two(visemes);
      frame.viseme.select1 = a.first;
      frame.viseme.select2 = b.first;
      // blend weighs select1 against select2; alone, a viseme's weight mixes it with neutral.
      frame.viseme.blend =
          b.second > 0 ? static_cast<int>(std::lround(63.0 * a.second / (a.second + b.second))) : a.second;
    }
    if (frame.has(2)) {
      const auto [a, b] = strongest_two(expressions);
      frame.expression = ExpressionFields{a.first, a.second, b.first, b.second, 0, 0};
    }
    return frame;
  }

  int clamp_and_warn(double value, int high, int low, std::int64_t cause, double t, std::string_view what) {
    const double rounded = std::round(value);  // halves away from zero
    if (rounded >= low && rounded <= high) return static_cast<int>(rounded);
    if (cause >= 0 && warned_clips_.insert(cause).second) {
      const Clip& clip = index_.clips[static_cast<std::size_t>(cause)];
      std::ostringstream message;
      message << what << " of '" << clip.target << "' reaches " << rounded << " at " << t << " s, outside " << low
              << ".." << high << "; clamped";
      warnings_.push_back(make_warning(codes::render::clamped, clip.source, message.str()));
    }
    return static_cast<int>(std::clamp(rounded, double(low), double(high)));
  }
};

}  // namespace

Location where_it_ends(const Timeline& timeline) {
  if (timeline.explicit_end) return timeline.end_source;
  const Clip* last = nullptr;
  for (const Clip& clip : timeline.clips)
    if (!last || clip.end >= last->end) last = &clip;
  return last ? last->source : Location{};
}

struct FrameStream::State {
  State(const Timeline& timeline, const RenderOptions& options, std::int64_t frames)
      : renderer(timeline, options), count(frames) {}
  FrameRenderer renderer;
  std::int64_t count;
};

FrameStream::FrameStream(std::unique_ptr<State> state) : state_(std::move(state)) {}
FrameStream::FrameStream(FrameStream&&) noexcept = default;
FrameStream& FrameStream::operator=(FrameStream&&) noexcept = default;
FrameStream::~FrameStream() = default;

Result<FrameStream> FrameStream::start(const Timeline& timeline, const RenderOptions& options) {
  if (options.fps <= 0) return make_error(codes::render::bad_frame_rate, Location{}, "the frame rate must be positive");
  const FrameBudget budget{options.fps, options.max_frames};
  if (budget.exceeded_by(timeline.end())) return frame_budget_error(timeline.end(), where_it_ends(timeline), budget);
  const auto count = static_cast<std::int64_t>(std::ceil(timeline.end() * options.fps - 1e-9));
  auto state = std::make_unique<State>(timeline, options, std::max<std::int64_t>(count, 0));
  if (auto resolved = state->renderer.resolve(); !resolved) return resolved.error();
  return FrameStream(std::move(state));
}

std::int64_t FrameStream::count() const { return state_->count; }
const std::string& FrameStream::name() const { return state_->renderer.options().name; }
int FrameStream::fps() const { return state_->renderer.options().fps; }
FapFrame FrameStream::frame(std::int64_t k) { return state_->renderer.frame_at(k); }
const Diagnostics& FrameStream::warnings() const { return state_->renderer.warnings(); }

Result<Rendered> render_frames(const Timeline& timeline, const RenderOptions& options) {
  Result<FrameStream> stream = FrameStream::start(timeline, options);
  if (!stream) return stream.error();
  Rendered out;
  out.frames.name = stream->name();
  out.frames.fps = stream->fps();
  out.frames.frames.reserve(static_cast<std::size_t>(stream->count()));
  for (std::int64_t k = 0; k < stream->count(); ++k) out.frames.frames.push_back(stream->frame(k));
  out.warnings = stream->warnings();
  return out;
}

}  // namespace fapc
