#include "fba/stream_reader.hpp"

#include <cmath>
#include <string>

namespace fapc::fba {

namespace {

bool is_start_code(std::uint32_t bits) { return (bits >> 8) == kStartCodePrefix; }

std::string hex_code(std::uint32_t code) {
  static const char* digits = "0123456789ABCDEF";
  std::string out = "0x";
  for (int shift = 28; shift >= 0; shift -= 4) out += digits[(code >> shift) & 15];
  return out;
}

}  // namespace

StreamReader::StreamReader(std::span<const std::uint8_t> bytes, const FbaDecodeOptions& options, FbaFrameSink sink)
    : options_(options), c_(bytes, options.file), sink_(std::move(sink)) {
  out_.info.bytes = bytes.size();
}

void StreamReader::skip_user_data() {
  while (c_.in.peek_bits(kStartCodeBits) == kUserDataStartCode) {
    c_.in.read_bits(kStartCodeBits);
    while (!c_.in.at_end() && !is_start_code(c_.in.peek_bits(kStartCodeBits))) c_.in.read_bits(8);
  }
}

Status StreamReader::read_stream_headers() {
  if (c_.in.peek_bits(kStartCodeBits) == kVisualObjectSequenceStartCode) {
    c_.in.read_bits(kStartCodeBits);
    out_.info.profile_and_level = static_cast<int>(c_.in.read_bits(kProfileLevelBits));
    skip_user_data();
  }
  if (c_.in.peek_bits(kStartCodeBits) == kVisualObjectStartCode) {
    c_.in.read_bits(kStartCodeBits);
    if (c_.in.read_bit() == 1) c_.in.read_bits(kVisualObjectVerIdBits + kVisualObjectPriorityBits);
    const std::int64_t type_byte = c_.in.byte_offset();
    const auto type = c_.in.read_bits(kVisualObjectTypeBits);
    if (type != kVisualObjectTypeFba)
      return c_.error_at(codes::fba::not_fba_object, type_byte,
                         "visual object type " + std::to_string(type) + " is not FBA (4)");
    // next_start_code(): a 0, then 1s to the byte boundary.
    const std::int64_t stuffing_byte = c_.in.byte_offset();
    bool stuffing_ok = c_.in.read_bit() == 0;
    while (!c_.in.aligned()) stuffing_ok = c_.in.read_bit() == 1 && stuffing_ok;
    if (!stuffing_ok)
      return c_.error_at(codes::fba::bad_stuffing, stuffing_byte, "bad stuffing after the visual object header");
    out_.info.visual_object_header = true;
    skip_user_data();
  }
  const std::int64_t byte = c_.in.byte_offset();
  const std::uint32_t code = c_.in.read_bits(kStartCodeBits);
  if (auto status = c_.check_inside("the stream header"); !status) return status;
  if (code != kFbaObjectStartCode && code != kLegacyObjectStartCode)
    return c_.error_at(codes::fba::no_object_start, byte,
                       "expected the FBA object start code 0x000001BA, found " + hex_code(code));
  return ok_status();
}

Result<StreamReader::Next> StreamReader::next_part() {
  const std::size_t here = c_.in.position();
  // Standard stuffing: a 0 then 1s to the boundary, or 0x7F when aligned. A plane start code
  // right at an aligned position is accepted too (the reference would skip a byte, D8).
  const auto stuffing_then_code = [&]() -> std::uint32_t {
    if (c_.in.aligned()) {
      if (is_start_code(c_.in.peek_bits(kStartCodeBits))) return c_.in.read_bits(kStartCodeBits);
      if (c_.in.read_bits(8) != kStuffingByte) return 0;
    } else {
      const int n = static_cast<int>(c_.in.bits_to_boundary());
      if (c_.in.read_bits(n) != (1u << (n - 1)) - 1) return 0;
    }
    const std::uint32_t code = c_.in.peek_bits(kStartCodeBits);
    if (!is_start_code(code)) return 0;
    return c_.in.read_bits(kStartCodeBits);
  };
  const std::int64_t code_byte = static_cast<std::int64_t>((here + 7) / 8);
  const std::uint32_t code = stuffing_then_code();
  if (code == 0 || c_.in.overrun()) {
    c_.in.seek(here);
    if (c_.in.at_end() || c_.in.size_bits() - here < 8)
      return c_.truncated_at(static_cast<std::int64_t>(c_.in.size_bits() / 8),
                             "stream ends without the end code 0x000001B1 (truncated?)");
    return Next::plane;  // planes of the reference encoder follow each other unaligned
  }
  if (code == kVisualObjectSequenceEndCode) return Next::end;
  if (code == kFbaObjectPlaneStartCode || code == kLegacyPlaneStartCode) {
    ++out_.info.plane_start_codes;
    return Next::plane;
  }
  return c_.error_at(codes::fba::unexpected_start_code, code_byte,
                     "unexpected start code " + hex_code(code) + " inside the FBA object");
}

void StreamReader::set_frame_rate(double rate) {
  FbaStreamInfo& info = out_.info;
  if (!info.frame_rate_sent) {
    info.frame_rate = rate;
    info.frame_rate_sent = true;
  } else if (rate != info.frame_rate && !rate_change_warned_) {
    out_.warnings.push_back(
        make_warning(codes::fba::frame_rate_change, Location::binary(c_.file, c_.in.byte_offset()),
                     "the frame rate changes to " + std::to_string(rate) + "; frames keep counting at the first rate"));
    rate_change_warned_ = true;
  }
}

Status StreamReader::read_temporal_header(bool intra, TemporalHeader& header) {
  if (intra && c_.in.read_bit() == 1) {  // is_frame_rate
    const std::int64_t byte = c_.in.byte_offset();
    const auto rate = c_.in.read_bits(kFrameRateBits);
    const auto sixteenths = c_.in.read_bits(kFrameRateSecondsBits);
    const bool ntsc = c_.in.read_bit() == 1;  // 1000/1001 in floating point (D7)
    const double value = (rate + sixteenths / 16.0) * (ntsc ? 1000.0 / 1001.0 : 1.0);
    if (value < 0.5)
      return c_.error_at(codes::fba::frame_rate_too_low, byte,
                         "frame rate " + std::to_string(value) + " is below 0.5 frames per second");
    set_frame_rate(value);
  }
  if (intra && c_.in.read_bit() == 1) {  // is_time_code
    const auto hours = c_.in.read_bits(kTimeCodeHoursBits);
    const auto minutes = c_.in.read_bits(kTimeCodeMinutesBits);
    if (auto status = c_.read_marker("in the time code"); !status) return status;
    const auto seconds = c_.in.read_bits(kTimeCodeSecondsBits);
    header.time_code = true;
    header.time_code_seconds = 3600 * hours + 60 * minutes + seconds;
  }
  if (c_.in.read_bit() == 1) {  // skip_frames
    std::uint32_t chunk;
    do {
      chunk = c_.in.read_bits(kSkipChunkBits);
      header.skip += chunk;
    } while (chunk == kSkipChunkContinues && !c_.in.overrun());
  }
  return c_.check_inside("a plane header");
}

void StreamReader::note_ranges(std::int64_t frame, std::int64_t byte, std::size_t bits) {
  FbaStreamInfo& info = out_.info;
  info.intra_planes.push_back({frame, byte, bits, face_.fap_quant, static_cast<int>(face_.mask.count())});
  for (int fap = kFirstLowLevelFap; fap <= kFapCount; ++fap) {
    const std::size_t i = FaceState::index(fap);
    if (!face_.mask.test(i)) continue;
    const FbaRange intra{face_.intra_min(fap), face_.intra_max(fap)};
    const FbaRange pred{face_.pred_min(fap), face_.pred_max(fap)};
    if (!info.ranged[i]) {
      info.intra_range[i] = intra;
      info.pred_range[i] = pred;
      info.ranged[i] = true;
      continue;
    }
    info.intra_range[i] = {std::min(intra.min, info.intra_range[i].min), std::max(intra.max, info.intra_range[i].max)};
    info.pred_range[i] = {std::min(pred.min, info.pred_range[i].min), std::max(pred.max, info.pred_range[i].max)};
  }
}

Status StreamReader::read_plane() {
  const std::size_t start = c_.in.position();
  const std::int64_t start_byte = c_.in.byte_offset();
  const bool intra = c_.in.read_bit() == 1;
  const auto object_mask = c_.in.read_bits(kObjectMaskBits);
  if (object_mask == 0)
    return c_.error_at(codes::fba::empty_plane_mask, start_byte,
                       "plane with fba_object_mask 00 (neither face nor body data; corrupt stream?)");
  TemporalHeader header;
  if (auto status = read_temporal_header(intra, header); !status) return status;
  ++out_.info.planes;

  const bool face = (object_mask & kObjectMaskFace) != 0;
  FapFrame frame;
  if (face) {
    FaceReader reader(c_, face_);
    if (intra) {
      if (auto status = reader.read_intra_header(); !status) return status;
    } else if (!face_.started) {
      return c_.error_at(codes::fba::predictive_before_intra, start_byte,
                         "a predictive face plane comes before the first intra plane");
    }
    if (auto status = reader.read_values(intra, frame); !status) return status;
  }
  if (object_mask & kObjectMaskBody) {
    if (!body_warned_) {
      out_.warnings.push_back(make_warning(codes::fba::body_ignored, Location::binary(c_.file, start_byte),
                                           "body animation (BAP) data is parsed and ignored: fapc handles faces only"));
      body_warned_ = true;
    }
    ++out_.info.body_planes;
    BodyReader body(c_, body_);
    if (auto status = body.skip(intra); !status) return status;
  }
  if (!face) return ok_status();  // a body plane's temporal header is body timing

  FbaStreamInfo& info = out_.info;
  const auto rate = info.frame_rate;
  frame.number = header.time_code ? std::llround(static_cast<double>(header.time_code_seconds) * rate) : next_number_;
  if (any_frame_ && frame.number <= last_number_)
    return c_.error_at(codes::fba::time_code_backwards, start_byte,
                       "the time code goes back to frame " + std::to_string(frame.number));
  // The frames the planes span so far, this one's skips included: a decoded sequence is written
  // gap-filled (.fap) and re-encoded, so skips count like frames (Limits::max_frames). Skips grow
  // by at most 255 per byte and time codes stay below 2^27 frames: no overflow here.
  const std::int64_t first = any_frame_ ? first_number_ : frame.number;
  if (const std::int64_t span = frame.number + header.skip + 1 - first; span > options_.max_frames) {
    Limits limits;
    limits.max_frames = options_.max_frames;
    return limit_error(Location::binary(c_.file, start_byte),
                       "the face planes span " + std::to_string(span) + " frames (skipped frames included)",
                       Limit::frames, limits);
  }
  if (intra) note_ranges(frame.number, start_byte, c_.in.position() - start);
  next_number_ = frame.number + header.skip + 1;
  ++info.face_planes;
  info.skipped_frames += header.skip;
  info.frames = next_number_ - first;
  if (!any_frame_) first_number_ = frame.number;
  any_frame_ = true;
  last_number_ = frame.number;
  if (sink_) return sink_(frame);
  out_.sequence.frames.push_back(frame);
  return ok_status();
}

Diagnostic StreamReader::explain(const Diagnostic& error) const {
  // Past the last byte the reader sees zeros, which trip other checks first (a marker bit of 0,
  // 23 zero bits); the real problem is the missing data.
  const auto size = static_cast<std::int64_t>(c_.in.size_bits() / 8);
  if (error.kind == ErrorKind::truncated) return error;
  if (c_.in.overrun() || error.where.byte_offset > size)
    return c_.truncated_at(size, "stream ends inside a plane (truncated?)");
  return error;
}

Result<DecodedFba> StreamReader::run() {
  if (auto status = read_stream_headers(); !status) return explain(status.error());
  for (;;) {
    auto next = next_part();
    if (!next) return explain(next.error());
    if (*next == Next::end) break;
    if (auto status = read_plane(); !status) return explain(status.error());
  }
  if (!c_.in.at_end())
    out_.warnings.push_back(
        make_warning(codes::fba::trailing_bytes, Location::binary(c_.file, c_.in.byte_offset()),
                     std::to_string(c_.in.size_bits() / 8 - static_cast<std::size_t>(c_.in.byte_offset())) +
                         " bytes after the end code are ignored"));
  FbaStreamInfo& info = out_.info;
  if (!info.frame_rate_sent && any_frame_)
    out_.warnings.push_back(make_warning(codes::fba::no_frame_rate, Location::binary(c_.file, 0),
                                         "the stream never gives its frame rate; assuming 30 frames per second"));
  out_.sequence.fps = static_cast<int>(std::lround(info.frame_rate));
  if (std::abs(info.frame_rate - out_.sequence.fps) > 1e-9)
    out_.warnings.push_back(make_warning(
        codes::fba::frame_rate_rounded, Location::binary(c_.file, 0),
        "frame rate " + std::to_string(info.frame_rate) + " rounded to " + std::to_string(out_.sequence.fps)));
  return std::move(out_);
}

}  // namespace fapc::fba
