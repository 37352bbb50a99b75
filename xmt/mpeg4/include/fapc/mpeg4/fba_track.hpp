// The FBA elementary stream as the MP4 writer takes it and the MP4 reader gives it back: a
// decoder configuration and one sample per coded FBA object plane. Nothing here knows how planes
// are coded; the codec fills this in (docs/mp4-and-xmta.md sections 6.2 and 6.3).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "fapc/codec/diagnostic.hpp"

namespace fapc::xmt {

using Bytes = std::vector<std::uint8_t>;

// ISO/IEC 14496-2 start codes that frame an FBA stream.
inline constexpr std::uint8_t kVisualObjectSequenceStartCode = 0xB0;
inline constexpr std::uint8_t kVisualObjectSequenceEndCode = 0xB1;
inline constexpr std::uint8_t kVisualObjectStartCode = 0xB5;
inline constexpr std::uint8_t kFbaObjectStartCode = 0xBA;
inline constexpr std::uint8_t kFbaObjectPlaneStartCode = 0xBB;

// profile_and_level_indication values for face animation (14496-2 Annex G).
inline constexpr std::uint8_t kSimpleFaceAnimationL1 = 0x61;
inline constexpr std::uint8_t kSimpleFaceAnimationL2 = 0x62;
inline constexpr std::uint8_t kSimpleFbaL1 = 0x63;
inline constexpr std::uint8_t kSimpleFbaL2 = 0x64;

struct FbaSample {
  Bytes bytes;                 // one byte-aligned fba_object_plane, starting 00 00 01 BB
  std::uint32_t duration = 1;  // in the track's timescale: frames covered (skipped frames + 1)
  bool sync = false;           // an intra plane
  friend bool operator==(const FbaSample&, const FbaSample&) = default;
};

struct FbaTrackInput {
  Bytes decoder_specific_info;   // fba_decoder_specific_info() for streams of this project
  std::uint32_t timescale = 25;  // ticks per second: the frame rate when it is an integer
  std::vector<FbaSample> samples;
  friend bool operator==(const FbaTrackInput&, const FbaTrackInput&) = default;
};

// The same track as views into bytes the caller holds: how a long stream reaches the writer
// without a copy of each sample (the caller keeps the bytes until the writing is done).
struct FbaSampleView {
  std::span<const std::uint8_t> bytes;
  std::uint32_t duration = 1;
  bool sync = false;
};
struct FbaTrackView {
  Bytes decoder_specific_info;
  std::uint32_t timescale = 25;
  std::vector<FbaSampleView> samples;
};
FbaTrackView view_of(const FbaTrackInput& track);

// The 14 bytes of docs/mp4-and-xmta.md section 6.2: visual object sequence header with the
// profile-level, visual object header of type FBA, FBA object start code.
Bytes fba_decoder_specific_info(std::uint8_t profile_level = kSimpleFbaL1);

// The profile_and_level_indication of a decoder configuration that begins with a visual object
// sequence header; an error naming the byte offset when it does not.
Result<std::uint8_t> fba_profile_level(const Bytes& decoder_specific_info, const std::string& file = {});

// "Simple FBA @ L1" for 0x63, and the other face animation profile-levels; "" for any other.
std::string_view fba_profile_name(std::uint8_t profile_level);

// Whether a visual decoder configuration declares an FBA object: its visual object header has
// visual_object_type 4 (14496-2 §6.2.2). MPEG-4 video uses the same 'mp4v' sample entry.
bool declares_fba_object(const Bytes& decoder_specific_info);

// Checks what the writer relies on: a configuration with a profile-level, at least one sample,
// every sample starting with the plane start code and lasting at least one tick, a positive
// timescale. The error names the sample.
Status check_fba_track(const FbaTrackInput& track);
Status check_fba_track(const FbaTrackView& track);

// The raw elementary stream (.fba) the track stands for: configuration, one 0x7F stuffing byte,
// the samples in order, the visual object sequence end code (docs/mp4-and-xmta.md section 6.3).
Bytes fba_stream_from_track(const FbaTrackInput& track);

}  // namespace fapc::xmt
