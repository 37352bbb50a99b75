#include "timeline_input.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "fapc/transcoder/audio_mix.hpp"
#include "fapc/transcoder/render.hpp"

namespace fapc::pipeline {

FrameBudget frame_budget_for(const ConvertOptions& options) {
  if ((!options.render && !options.renders_later) || options.duration) return FrameBudget{};
  return FrameBudget{options.fps, options.limits.max_frames};
}

Result<Profile> profile_for(const ConvertOptions& options) {
  if (!options.profile) return default_profile();
  return load_profile(*options.profile);
}

namespace {

Diagnostic named_after(Diagnostic error, const std::string& name) {
  if (error.where.file.empty()) error.where.file = name;  // a whole-animation problem
  return error;
}

}  // namespace

RenderOptions render_options_for(const std::string& name, const Profile& profile, const ConvertOptions& options) {
  RenderOptions render;
  render.fps = options.fps;
  render.max_frames = options.limits.max_frames;
  render.profile = &profile;
  render.name = std::filesystem::path(name).stem().string();
  return render;
}

Result<FrameStream> stream_frames(const Timeline& timeline, const std::string& name, const Profile& profile,
                                  const ConvertOptions& options) {
  Result<FrameStream> stream = FrameStream::start(timeline, render_options_for(name, profile, options));
  if (!stream) return named_after(stream.error(), name);
  return stream;
}

Result<std::optional<AudioTrack>> mixed_audio(const Timeline& timeline, const ConvertOptions& options) {
  return mix_audio(timeline.audio, static_cast<double>(options.limits.max_frames) / options.fps, options.limits);
}

namespace {

// render_frames without its frames: the same stream, so the same checks, errors and warnings,
// each frame counted and dropped. What the summary needs (count, FAPs used) goes to `seen`.
Result<Rendered> render_not_kept(const Timeline& timeline, const RenderOptions& options, FramesSeen& seen) {
  Result<FrameStream> stream = FrameStream::start(timeline, options);
  if (!stream) return stream.error();
  Rendered out;
  out.frames.name = stream->name();
  out.frames.fps = stream->fps();
  seen.count = static_cast<std::size_t>(stream->count());
  seen.fps = stream->fps();
  for (std::int64_t k = 0; k < stream->count(); ++k) seen.faps |= stream->frame(k).mask;
  out.warnings = stream->warnings();
  return out;
}

}  // namespace

Result<Loaded> loaded_from_timeline(Timeline timeline, const std::string& name, const Profile& profile,
                                    const ConvertOptions& options, Diagnostics warnings, nlohmann::ordered_json facts) {
  if (options.duration) {
    timeline.explicit_end = *options.duration;
    timeline.end_source = Location::whole_file(name);  // the whole input, ended by --duration
  }
  if (!options.render) {  // an XMT-Omega include: its clips are placed, its frames never used
    Loaded loaded;
    loaded.timeline = std::move(timeline);
    loaded.warnings = std::move(warnings);
    loaded.facts = json_value(std::move(facts));
    return loaded;
  }
  // The outputs' own limits on the length first: a four-hour video is refused before its 360,000
  // frames are rendered. A timeline past the frame limit is left to the renderer, which says so.
  if (options.check_length && !frame_budget_for(options).exceeded_by(timeline.end())) {
    const auto frames = static_cast<std::int64_t>(std::max(0.0, std::ceil(timeline.end() * options.fps - 1e-9)));
    if (Status fits = options.check_length(frames, options.fps, where_it_ends(timeline)); !fits)
      return named_after(fits.error(), name);
  }
  const RenderOptions render = render_options_for(name, profile, options);
  FramesSeen seen;
  Result<Rendered> rendered =
      options.frames ? render_frames(timeline, render) : render_not_kept(timeline, render, seen);
  if (!rendered) return named_after(rendered.error(), name);
  Result<std::optional<AudioTrack>> audio = mixed_audio(timeline, options);
  if (!audio) return audio.error();
  Loaded loaded;
  loaded.audio = std::move(*audio);
  loaded.frames = std::move(rendered->frames);
  if (!options.frames) loaded.frames_not_kept = seen;
  if (options.curves) loaded.curves = render_curves(timeline, CurveOptions{options.fps, 1e-6});
  loaded.timeline = std::move(timeline);
  loaded.warnings = std::move(warnings);
  loaded.facts = json_value(std::move(facts));
  loaded.warnings.insert(loaded.warnings.end(), rendered->warnings.begin(), rendered->warnings.end());
  return loaded;
}

}  // namespace fapc::pipeline
