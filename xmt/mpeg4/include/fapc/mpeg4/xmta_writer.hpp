// XMT-A documents (ISO/IEC 14496-11, namespace urn:mpeg:mpeg4:xmta:schema:2002) of the project's
// face scene, in the shape GPAC itself dumps and reloads losslessly: an initial object descriptor
// with Profiles and the system streams' ES descriptors (BIFSConfig with its size), then a Body
// whose first `par` (time 0, a random access point) replaces the scene. Two modes:
//  - FBA: the same scene as the MP4 writer's, plus an ObjectDescriptorUpdate at time 0 declaring
//    the FBA stream (with its decoder configuration and a StreamSource naming where it is);
//  - commands: no FBA stream; the animation is timed BIFS Replace commands on the FAP, Viseme
//    and Expression nodes' fields, for players without an FBA decoder.
// Choices: docs/mp4-and-xmta.md.
#pragma once

#include <cstdint>
#include <string>

#include "fapc/codec/fap_sequence.hpp"
#include "fapc/mpeg4/fba_track.hpp"

namespace fapc::mpeg4 {

inline constexpr const char* kXmtaNamespace = "urn:mpeg:mpeg4:xmta:schema:2002";

// The voice beside the face: its AudioSpecificConfig and rate, and the StreamSource url of its
// access units (e.g. "face.mp4#11"; empty writes none).
struct XmtaAudio {
  Bytes decoder_specific_info;
  std::uint32_t sample_rate = 0;
  std::string stream_source;
};

// `stream_source`: the StreamSource url of the FBA stream (e.g. "face.mp4#10"); empty writes no
// StreamSource element. With `audio`, the object descriptor update also declares the audio
// stream (OD 11) and the scene plays it: Sound2D { source AudioSource { url "od:11" } }, as the
// MP4 writer does.
std::string write_xmta_fba_scene(const Bytes& decoder_specific_info, const std::string& stream_source,
                                 const XmtaAudio* audio = nullptr);

// One `par` per frame time at which a masked value changes (values hold until changed, as BIFS
// fields do). A frame numbered 0 goes into the initial scene.
std::string write_xmta_commands(const FapSequence& frames);

}  // namespace fapc::mpeg4
