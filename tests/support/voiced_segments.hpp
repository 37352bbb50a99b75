// Where a voice track sounds, measured on its samples: what the speech sync tests of FML and BML
// hold the face's timing against.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "fapc/codec/fap_sequence.hpp"
#include "fapc/timeline/audio.hpp"

namespace fapc::test {

struct Segment {
  double begin = 0;
  double end = 0;
};

// Where the voice sounds: 10 ms windows whose RMS is above 1/30 of the loudest window's (-30 dB),
// joined across quiet stretches shorter than `min_pause` (stop closures, not pauses).
inline std::vector<Segment> voiced_segments(const AudioTrack& track, double min_pause) {
  const std::size_t window = static_cast<std::size_t>(track.sample_rate / 100);
  std::vector<double> rms;
  for (std::size_t at = 0; at + window <= track.samples.size(); at += window) {
    double sum = 0;
    for (std::size_t i = at; i < at + window; ++i) sum += double(track.samples[i]) * track.samples[i];
    rms.push_back(std::sqrt(sum / double(window)));
  }
  double loudest = 0;
  for (double r : rms) loudest = std::max(loudest, r);
  std::vector<Segment> out;
  for (std::size_t w = 0; w < rms.size(); ++w) {
    if (rms[w] < loudest / 30) continue;
    const double t = track.start + double(w) * 0.01;
    if (!out.empty() && t - out.back().end < min_pause) {
      out.back().end = t + 0.01;
    } else {
      out.push_back({t, t + 0.01});
    }
  }
  return out;
}

// The onsets of the voiced stretches, joined across gaps shorter than min_pause.
inline std::vector<double> voiced_onsets(const AudioTrack& track, double min_pause) {
  std::vector<double> onsets;
  for (const Segment& segment : voiced_segments(track, min_pause)) onsets.push_back(segment.begin);
  return onsets;
}

// The time of the frame before the first where FAP `fap` is away from 0 (a behaviour that moves
// it starts between that frame and the next), or -1 when it never moves.
inline double first_move(const FapSequence& frames, int fap) {
  for (const FapFrame& f : frames.frames)
    if (f.has(fap) && f.value(fap) != 0) return double(f.number - 1) / frames.fps;
  return -1;
}

}  // namespace fapc::test
