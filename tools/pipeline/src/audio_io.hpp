// The voice in an .mp4: an AudioTrack coded as AAC-LC and placed on the face's clock for the MP4
// writer, and an MP4 audio track decoded back (docs/mp4-and-xmta.md section 1.2).
#pragma once

#include <optional>
#include <string>

#include "fapc/codec/limits.hpp"
#include "fapc/mpeg4/audio_track.hpp"
#include "fapc/timeline/audio.hpp"

namespace fapc::pipeline {

// The track for write_mp4, or nullopt when there is no sound to carry (no samples, or all of them
// before the face starts). Sound before the face's time 0 is cut; sound that ends before the face
// (`face_seconds` long) is followed by silence up to the face's end, so that the audio track's
// presentation (its delay, then its sound) spans the face track's. `where` names the output.
Result<std::optional<mpeg4::AudioTrackInput>> pack_audio_track(const AudioTrack& audio, double face_seconds,
                                                               const std::string& where, const Limits& limits);

// The sound of an MP4 audio track, starting at its delay. The decoded size is limited by
// --max-decompressed-bytes (two bytes a sample). `where` names the file.
Result<AudioTrack> unpack_audio_track(const mpeg4::AudioTrackInput& track, const std::string& where,
                                      const Limits& limits);

}  // namespace fapc::pipeline
