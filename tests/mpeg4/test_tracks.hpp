// Hand-made FBA tracks for the MP4 tests: the real decoder configuration and samples that are
// plane start codes followed by a few bytes. Enough for structure tests and outside readers,
// which never decode the planes.
#pragma once

#include "fapc/codec/fap_sequence.hpp"
#include "fapc/mpeg4/fba_track.hpp"

namespace fapc::xmt::test {

inline FbaTrackInput hand_made_track(int samples = 10, std::uint32_t timescale = 25, int intra_every = 5) {
  FbaTrackInput t;
  t.decoder_specific_info = fba_decoder_specific_info();
  t.timescale = timescale;
  for (int i = 0; i < samples; ++i) {
    FbaSample s;
    s.bytes = {0x00,
               0x00,
               0x01,
               kFbaObjectPlaneStartCode,
               static_cast<std::uint8_t>(i),
               0x55,
               static_cast<std::uint8_t>(0x80 | i),
               0x7F};
    s.sync = i % intra_every == 0;
    s.duration = 1;
    t.samples.push_back(std::move(s));
  }
  return t;
}

// A frame at time 0 with a viseme, open_jaw and head_yaw: the initial state of a commands scene.
inline const FapFrame& frame_with_viseme() {
  static const FapFrame frame = [] {
    FapFrame f;
    f.mask.set(0);
    f.viseme.select1 = 4;
    f.set(3, 120);
    f.set(49, 1700);
    return f;
  }();
  return frame;
}

}  // namespace fapc::xmt::test
