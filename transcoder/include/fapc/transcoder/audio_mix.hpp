// The timeline's audio clips mixed into the one track writers carry (docs/speech.md, "Audio").
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "fapc/codec/diagnostic.hpp"
#include "fapc/codec/limits.hpp"
#include "fapc/timeline/audio.hpp"

namespace fapc {

// Every clip resampled (linear interpolation) to the highest rate among them and summed, with
// saturation at the 16-bit range; the track starts at the earliest clip (or 0, the face's start,
// when that is earlier: clips before 0 are cut). No clips: nullopt. A track longer than
// `max_seconds` is a limit_exceeded error at the clip that reaches furthest, checked before
// allocating.
// The part of `clip`, moved by `shift` seconds, that lies in [from, to): one run of an utterance
// (a repeat, a run cut by its container). nullopt when nothing is left.
std::optional<AudioClip> placed_audio(const AudioClip& clip, double shift, double from, double to);

// How many samples placed_audio(clip, shift, from, to) would copy: front ends sum it over every
// run of a repeated talk or recording and check the sum against Limits::max_audio_samples
// before placing any (a 10^5-fold repeatCount of a recording would otherwise copy it 10^5 times).
double placed_samples(const AudioClip& clip, double shift, double from, double to);

// A track of more than limits.max_audio_samples samples is refused the same way (a 1 Hz clip
// mixed with a 384 kHz one, clips hours apart). The mix is summed block by block, so nothing but
// the track itself is allocated in proportion to it.
Result<std::optional<AudioTrack>> mix_audio(const std::vector<AudioClip>& clips, double max_seconds,
                                            const Limits& limits = {});

}  // namespace fapc
