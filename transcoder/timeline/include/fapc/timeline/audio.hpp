// Sound that travels with the timeline: speech synthesised from text, or a recording (WAV) that
// a script names. Plain values, no I/O; docs/timeline.md places it on the clock.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "fapc/codec/diagnostic.hpp"

namespace fapc::timeline {

// One piece of sound placed on the timeline: mono 16-bit PCM at its own rate, starting at `begin`
// (absolute seconds, like Clip::begin). Front ends add one per spoken text or audio element.
struct AudioClip {
  double begin = 0;
  int sample_rate = 0;  // Hz
  std::vector<std::int16_t> samples;
  Location source;  // the element it came from, for warnings and `fapc info`
  // Spelled out: Location has no operator==, so a defaulted one is deleted (clang refuses it
  // under -Werror, which broke the fuzz build).
  friend bool operator==(const AudioClip& a, const AudioClip& b) {
    return a.begin == b.begin && a.sample_rate == b.sample_rate && a.samples == b.samples &&
           a.source.file == b.source.file && a.source.line == b.source.line && a.source.column == b.source.column &&
           a.source.byte_offset == b.source.byte_offset;
  }
};

// What writers take: every clip of a timeline mixed into one mono track at one rate, starting at
// `start` seconds on the face's clock (the face track starts at 0).
struct AudioTrack {
  int sample_rate = 0;
  double start = 0;
  std::vector<std::int16_t> samples;
  // Where errors about the whole track point: the clip that set its rate (the first at the
  // highest rate); empty when the track was not mixed from clips (an .mp4's voice). Not part of
  // the sound: == leaves it out.
  Location source;

  double duration() const { return sample_rate > 0 ? double(samples.size()) / sample_rate : 0; }
  friend bool operator==(const AudioTrack& a, const AudioTrack& b) {
    return a.sample_rate == b.sample_rate && a.start == b.start && a.samples == b.samples;
  }
};

}  // namespace fapc::timeline

// Until the tree names the model fapc::timeline::..., the names are seen from fapc as before.
namespace fapc {
using namespace timeline;
}  // namespace fapc
