// WAV files (RIFF WAVE, PCM 16-bit): the few lines their header needs, read and written here.
// Other encodings (float, 8/24/32-bit, compressed) are refused by name; several channels are
// mixed down to mono, since fapc carries one voice.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "fapc/codec/diagnostic.hpp"
#include "fapc/timeline/audio.hpp"

namespace fapc {

// Errors at `FILE: byte N`: not RIFF/WAVE, a chunk that overruns the file, no fmt or data chunk,
// an encoding other than PCM 16-bit, a rate outside 1..384000 Hz.
Result<AudioClip> read_wav(std::string_view bytes, const std::string& file_name);

// A mono 16-bit PCM WAV file of the track. A WAV has no clock offset, so a track that starts
// after 0 begins with that much silence: sample 0 of the file is the face's time 0.
std::string wav_bytes(const AudioTrack& track);

}  // namespace fapc
