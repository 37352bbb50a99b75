// What every timeline front end (Mimic, FML, XMT-Omega) does after lowering: render the frames and
// the curves with the user's options and keep the timeline for per-clip plots.
#pragma once

#include <string>

#include "fapc/pipeline/loaded.hpp"
#include "fapc/pipeline/options.hpp"
#include "fapc/transcoder/frame_budget.hpp"
#include "fapc/transcoder/profile.hpp"
#include "fapc/transcoder/render.hpp"

namespace fapc::pipeline {

// The frame budget a front end checks as soon as it has scheduled its input, before its clips are
// made: the rate and limit the timeline will be rendered at. None (fps 0) when its frames are never
// made (an XMT-Omega include) or when --duration sets the end (rendering checks that, at the input).
FrameBudget frame_budget_for(const ConvertOptions& options);

// The profile of --profile, or the default one.
Result<Profile> profile_for(const ConvertOptions& options);

// How a timeline read from `name` is rendered: --fps, --max-frames, the profile, the name.
RenderOptions render_options_for(const std::string& name, const Profile& profile, const ConvertOptions& options);

// Frames of `timeline` one at a time (timeline_source.cpp), with render_frames' checks and errors
// as loaded_from_timeline reports them; `profile` must outlive the stream.
Result<FrameStream> stream_frames(const Timeline& timeline, const std::string& name, const Profile& profile,
                                  const ConvertOptions& options);

// The timeline's voice mixed into one track, as long as the frames may last.
Result<std::optional<AudioTrack>> mixed_audio(const Timeline& timeline, const ConvertOptions& options);

// Frames at options.fps (clamp warnings appended to `warnings`), curves, and the timeline itself;
// the timeline alone when options.render is false. `facts` become Loaded::facts.
Result<Loaded> loaded_from_timeline(Timeline timeline, const std::string& name, const Profile& profile,
                                    const ConvertOptions& options, Diagnostics warnings,
                                    nlohmann::ordered_json facts = nlohmann::ordered_json::object());

// A script row's loader: `read(profile)` gives a document with `timeline` and `warnings`, and
// `facts_of(document)` what `fapc info` tells of it (made only when asked).
template <class Read, class FactsOf>
Result<Loaded> load_script(const std::string& path, const ConvertOptions& options, Read&& read, FactsOf&& facts_of) {
  Result<Profile> profile = profile_for(options);
  if (!profile) return profile.error();
  auto document = read(*profile);
  if (!document) return document.error();
  auto facts = options.facts ? facts_of(*document) : nlohmann::ordered_json::object();
  return loaded_from_timeline(std::move(document->timeline), path, *profile, options, std::move(document->warnings),
                              std::move(facts));
}

}  // namespace fapc::pipeline
