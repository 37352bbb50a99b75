// The resource policy (docs/security.md, "Resource limits"): every number read from an input that
// would make fapc allocate or work in proportion to it is checked against one of these limits
// *before* the allocation, and passing one is an ErrorKind::limit_exceeded error that names the
// limit and the command-line option that raises it. One struct, passed to every reader and
// renderer, so the frame cap of the renderer and of the decoder cannot disagree again.
#pragma once

#include <cstdint>
#include <string>

#include "fapc/codec/diagnostic.hpp"

namespace fapc {

struct Limits {
  // Frames one sequence may span, gaps included (writers fill gaps, the Algebra allocates a slot
  // per frame): rendered from a timeline, decoded from a stream, read from a .fap file, made by a
  // combination. 2^20 frames is 11.6 hours at 25 fps; some 350 MB of frames in memory.
  std::int64_t max_frames = std::int64_t{1} << 20;
  // Scheduled runs (clips after repeats and template expansion) of one Mimic, FML or XMT-Omega
  // script (and the actions of a Mimic program with its macros expanded): a 1 ms animation
  // repeated for a day would otherwise make 86 million clips. Four times the 10^6 elements of a
  // large honest script, whose repeats and templates make more runs than elements
  // (docs/security.md, "Resource limits").
  std::int64_t max_runs = 4'000'000;
  // Bytes a compressed (gzip) input may inflate to, whatever its size.
  std::int64_t max_decompressed_bytes = std::int64_t{1} << 30;
  // ... and at most this many times its compressed size once past kExpansionFloor: a 1 MB gzip
  // bomb would otherwise inflate to 1 GB (deflate reaches about 1000:1).
  double max_expansion = 100;
  // Audio samples one mixed voice track may hold (docs/speech.md, "Audio on the timeline"): the
  // span from its first sound to its last (or to the face's end, or from time 0 for a .wav) at
  // the highest rate among its clips. 2^27 is 101 minutes at 22,050 Hz, 47 at 48 kHz; 256 MB of
  // 16-bit samples.
  std::int64_t max_audio_samples = std::int64_t{1} << 27;
  // Bytes of talk text one document hands to the speech engine, all talks together (64 KiB is
  // about an hour of honest text at 175 words per minute).
  std::int64_t max_speech_text_bytes = std::int64_t{1} << 16;
  // Seconds of speech one document may synthesise, all talks together: estimated from the text
  // before synthesis, and counted during it. Synthesis costs some 0.004 s per second of speech.
  double max_speech_seconds = 1800;
  // Pixels of one picture (--size) of a .png, .webm or .html output: the VP9 encoder's buffers
  // grow with it (some 100 bytes a pixel: 7680x4320 took 3.6 GB). 2^22 is 2560x1600 or 2048x2048.
  std::int64_t max_frame_pixels = std::int64_t{1} << 22;
  // Pixels of a .png contact sheet (--sheet N cells of --size each), held whole at 4 bytes a
  // pixel while drawn and coded: 2^27 is 512 MB, and lets the largest sheet at the default size
  // through (400 cells of 640x480 are 12800x9600).
  std::int64_t max_sheet_pixels = std::int64_t{1} << 27;
  // Pixels a .webm or .html video encodes in all (pictures x pixels of each), estimated from the
  // animation's duration and the picture rate before any picture is drawn: the video's time
  // (docs/security.md, "Resource limits").
  std::int64_t max_video_pixels = std::int64_t{2} << 30;
};

// Below this many inflated bytes the expansion factor is not checked (tiny, very regular files
// compress far better than 100:1 and are harmless).
inline constexpr std::int64_t kExpansionFloor = std::int64_t{1} << 20;

enum class Limit {
  frames,
  runs,
  decompressed_bytes,
  expansion,
  audio_samples,
  speech_text,
  speech_seconds,
  frame_pixels,
  sheet_pixels,
  video_pixels
};

// "--max-frames" ... : the option of `fapc compile` (and every command that reads inputs) that
// raises the limit.
const char* limit_option(Limit which);
// The limit's value as text ("1048576", "100").
std::string limit_value(Limit which, const Limits& limits);

// ErrorKind::limit_exceeded at `where`: "WHAT: more than the limit of N UNIT (--max-x N raises
// it)". `what` says what the input asks for, e.g. "the animation lasts 1e+08 s, 2500000000
// frames at 25 fps".
Diagnostic limit_error(Location where, const std::string& what, Limit which, const Limits& limits);

}  // namespace fapc
