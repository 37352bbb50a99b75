// MPEG-4 face animation streams (the face part of the FBA object of ISO/IEC 14496-2, Simple FBA
// profile): FAP frames in, bytes out, and back. The encoder writes what the reference decoder
// reads (docs/fba.md); the decoder reads any such stream, parses past body animation data, and
// reports every problem as a Diagnostic with the byte offset. Nothing here prints.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "fapc/codec/diagnostic.hpp"
#include "fapc/codec/fap_sequence.hpp"
#include "fapc/codec/limits.hpp"

namespace fapc {

// ---- encoding ----------------------------------------------------------------------------------

enum class FbaRangeMode {
  fit,  // each intra plane signals the smallest ranges that cover its group of planes
  max,  // every range at its largest, +-1860 quantised units
};

enum class FbaMaskMode {
  fit,   // the encoder may send a FAP the input leaves out (as 0), or leave out one it sends,
         // wherever no player shows a difference, to save intra planes (docs/fba.md 2, "Masks")
  keep,  // every plane carries exactly its frame's mask
};

struct FbaEncodeOptions {
  int quant = 1;         // fap_quant 0..31: step = FAP quantiser (QP) x quant; 0 is lossless
  int intra_period = 0;  // >0: at most this many planes from one intra plane to the next;
                         // 0: intra planes only where needed (first frame, mask changes)
  FbaRangeMode ranges = FbaRangeMode::fit;
  FbaMaskMode masks = FbaMaskMode::fit;
  bool align_planes = false;     // start every plane with its start code and end it byte-aligned,
                                 // so each plane is one MP4 sample (docs/mp4-and-xmta.md section 6.3)
  bool list_every_mask = false;  // mask type 01 (bits listed) for every group, the layout of the
                                 // test vector (docs/fba-bitstream.md 11); by default empty groups
                                 // get type 00 and full ones 11, which needs no mask bits
  // The most frames the sequence may span (gaps included): the decoder's limit, so that fapc
  // never writes a stream it refuses to read back (Limits::max_frames).
  std::int64_t max_frames = Limits{}.max_frames;
  // Where frame `number`'s FAP `fap` came from, for the errors about one value of one frame (a
  // value the stream cannot carry, a FAP 1/2 field out of range): the encoder sees frames, the
  // caller knows the lines they were read from. Unset, such errors carry no location.
  std::function<Location(std::int64_t number, int fap)> locate = {};
};

// Where one plane (one frame, plus the frames it skips) sits in the output.
struct CodedPlane {
  std::size_t offset = 0;      // first byte holding the plane's bits
  std::size_t size = 0;        // bytes from offset to the last byte holding its bits
  std::size_t bit_offset = 0;  // exact position and length in bits (planes share bytes unless
  std::size_t bit_size = 0;    //   align_planes is set)
  bool intra = false;
  std::int64_t first_frame = 0;  // the frame number it carries
  int frames = 1;                // frames it covers: 1 + number_of_frames_to_skip
};

struct EncodedFba {
  std::vector<std::uint8_t> bytes;  // the raw stream: 0x000001BA, planes, stuffing, 0x000001B1
  std::size_t header_size = 0;      // bytes before the first plane (start code, and the 0x7F
                                    // stuffing byte when planes are aligned)
  std::vector<CodedPlane> planes;
};

// The highest frame rate the stream can code (8 bits, docs/fba-bitstream.md).
inline constexpr int kMaxFbaFrameRate = 255;

// Frame numbers are coded relative to the first frame; gaps become skip counts. Errors (a value
// no range can carry, a frame rate above 255, bad FAP 1/2 fields) carry no file name: the caller
// knows which input the sequence came from.
Result<EncodedFba> encode_fba(const FapSequence& sequence, const FbaEncodeOptions& options = {});

// The same encoder fed frame by frame, for sequences too long to hold (a frame file read in
// slices, a timeline rendered frame by frame). It takes the frames twice: a first pass checks
// every frame (so that no error can come after output has begun) and gathers what fitting masks
// needs from the whole sequence (32 bytes a frame); the second pass codes them, holding one group
// of planes and the frame after it. The bytes are those encode_fba gives for the same frames.
class FbaEncoder {
 public:
  explicit FbaEncoder(const FbaEncodeOptions& options = {});
  ~FbaEncoder();
  FbaEncoder(FbaEncoder&&) noexcept;
  FbaEncoder& operator=(FbaEncoder&&) noexcept;

  // First pass: every frame, in order. Fails on the first frame encode_fba would refuse, or on
  // the options (which every call reports).
  Status check(const FapFrame& frame);
  // Before the first add (and before or after the first pass): the sequence's frame rate, which
  // the stream must be able to carry (1 to 255). Fails on the options first, as encode_fba does.
  Status start(int fps);
  // Second pass: the same frames, in the same order, after every one was checked.
  Status add(const FapFrame& frame);
  // After the last add: the stream.
  Result<EncodedFba> finish();

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// The decoder configuration an MP4 track carries (docs/mp4-and-xmta.md section 6.2): visual object
// sequence header with profile-level 0x63 (Simple FBA L1), visual object header of type FBA, and
// the FBA object start code. 14 bytes.
std::array<std::uint8_t, 14> fba_decoder_specific_info();

// The largest error the round trip may introduce on a FAP (3..68): half its quantiser step.
std::int64_t fba_tolerance(int fap, int quant);

// ---- decoding ----------------------------------------------------------------------------------

struct FbaDecodeOptions {
  std::string file = "stream.fba";  // names the input in diagnostics
  // Refuse streams whose face planes span more frames, skipped frames included (Limits).
  std::int64_t max_frames = Limits{}.max_frames;
};

// A signalled range of one FAP, in quantised units.
struct FbaRange {
  std::int32_t min = 0;
  std::int32_t max = 0;
};

struct FbaIntraPlane {
  std::int64_t frame = 0;        // frame number
  std::int64_t byte_offset = 0;  // where the plane starts
  std::size_t bits = 0;          // its length
  int fap_quant = 0;
  int faps = 0;  // FAPs in its mask
};

struct FbaStreamInfo {
  std::size_t bytes = 0;
  int profile_and_level = -1;  // from a visual object sequence header, -1 without
  bool visual_object_header = false;
  std::size_t planes = 0;  // face and body planes
  std::size_t face_planes = 0;
  std::size_t body_planes = 0;        // planes that carry body (BAP) data, parsed and ignored
  std::size_t plane_start_codes = 0;  // planes introduced by 0x000001BB
  std::int64_t frames = 0;            // frames the face planes cover, skips included
  std::int64_t skipped_frames = 0;
  double frame_rate = 30.0;  // 30 when the stream never says (the reference's rule)
  bool frame_rate_sent = false;
  std::vector<FbaIntraPlane> intra_planes;
  // Per FAP (index fap - 1), the widest ranges signalled for it; `ranged` says whether any was.
  std::array<bool, kFapCount> ranged{};
  std::array<FbaRange, kFapCount> intra_range{};
  std::array<FbaRange, kFapCount> pred_range{};

  double bits_per_frame() const {
    return frames > 0 ? static_cast<double>(bytes) * 8.0 / static_cast<double>(frames) : 0.0;
  }
};

struct DecodedFba {
  FapSequence sequence;  // one frame per face plane, numbered by the stream's timing
  FbaStreamInfo info;
  Diagnostics warnings;  // body data ignored, rounded frame rate, bytes after the end code ...
};

Result<DecodedFba> decode_fba(std::span<const std::uint8_t> bytes, const FbaDecodeOptions& options = {});

// The same decoding, each frame handed to `sink` as it is decoded instead of kept (the result's
// sequence has no frames), for streams too long to hold as frames. The checks, warnings, errors
// and statistics are decode_fba's; an error the sink returns stops the decoding.
using FbaFrameSink = std::function<Status(const FapFrame&)>;
Result<DecodedFba> decode_fba(std::span<const std::uint8_t> bytes, const FbaDecodeOptions& options,
                              const FbaFrameSink& sink);

// ---- verification ------------------------------------------------------------------------------

// Decodes `encoded` and checks it against `input`: the same frames and numbers (relative to the
// first); every FAP 3..68 shows within fba_tolerance() of the input (exact at quant 0) to a player
// that holds absent FAPs, to one that shows them at 0, and to one that copies them from their
// left/right partner, and with FbaMaskMode::keep the masks are the same; viseme and expression
// fields exact but for blends and intensities (within half of quant); then re-encodes the decoded
// frames with the same options and checks the bytes are identical. The error's message starts
// with "verification failed" and names the frame and FAP.
Status verify_fba(const FapSequence& input, const EncodedFba& encoded, const FbaEncodeOptions& options,
                  const std::string& file = "stream.fba");

// The same verification for an input too long to hold: its `count` frames at `fps` come again one
// at a time from `next` (each call the next frame, in order, valid until the next call; never
// called more than `count` times). The stream is decoded twice, a frame at a time (to compare,
// then to encode again), so nothing but the encoder's group of frames is held; the checks, their
// order and their messages are the other verify_fba's (which is this one over the sequence).
using FbaInputFrames = std::function<const FapFrame&()>;
Status verify_fba(std::size_t count, int fps, const FbaInputFrames& next, const EncodedFba& encoded,
                  const FbaEncodeOptions& options, const std::string& file = "stream.fba");

}  // namespace fapc
