// Writes an ISO base media file (ISO/IEC 14496-12, -14) with an MPEG-4 scene and an FBA stream:
// ftyp; moov with mvhd, iods, a BIFS scene track, an OD track whose object descriptor update binds
// the FBA stream, and the FBA track; mdat. Layout and choices: docs/mp4-and-xmta.md.
#pragma once

#include <cstdint>
#include <functional>
#include <span>

#include "fapc/codec/diagnostic.hpp"
#include "fapc/mpeg4/audio_track.hpp"
#include "fapc/mpeg4/bifs.hpp"
#include "fapc/mpeg4/fba_track.hpp"

namespace fapc::mpeg4 {

// Track IDs (which are also the ES_IDs) and the FBA stream's object descriptor ID. 10 for the
// FBA track is what GPAC gives it when it builds the same file from the project's XMT-A
// (binaryID 10), so both routes produce the same layout.
inline constexpr std::uint32_t kSceneTrackId = 1;
inline constexpr std::uint32_t kOdTrackId = 2;
inline constexpr std::uint32_t kFbaTrackId = 10;
inline constexpr std::uint16_t kFbaObjectDescriptorId = 10;
inline constexpr std::uint32_t kSystemsTimescale = 1000;  // scene, OD and movie timescale
// The voice: the next track and OD IDs after the FBA stream's (docs/mp4-and-xmta.md section 1.2).
inline constexpr std::uint32_t kAudioTrackId = 11;
inline constexpr std::uint16_t kAudioObjectDescriptorId = 11;

// The file's bytes, or why they cannot be written (a track check_fba_track or check_audio_track
// rejects, a file over 4 GiB). With `audio`, a fourth track carries it, the OD access unit
// declares it and the scene plays it (Sound2D/AudioSource); without, the bytes are those of the
// three-track file.
Result<Bytes> write_mp4(const FbaTrackInput& fba, const AudioTrackInput* audio = nullptr);

// The same bytes handed to `sink` in order, in pieces of about 1 MB, for files too long to hold:
// the writer keeps the sample table (some 12 bytes a sample), not the file. The first error, the
// writer's or the sink's, stops the writing.
using Mp4Sink = std::function<Status(std::span<const std::uint8_t>)>;
Status write_mp4(const FbaTrackView& fba, const AudioTrackInput* audio, const Mp4Sink& sink);

}  // namespace fapc::mpeg4
