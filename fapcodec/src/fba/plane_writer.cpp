#include "fba/plane_writer.hpp"

namespace fapc::fba {

namespace {

// The reference decoder decodes a segment with 16 bits of look-ahead and counts zeros as it goes
// (docs/fba-bitstream.md sections 6.4 to 6.6): a segment's trailing zeros, a one-bit stuffing '0'
// and the 23 zeros of a start code make a run past 22 inside its look-ahead, which it takes for a
// missing stuffing bit. At most 8 zeros before a start code keep every run well short of that.
constexpr std::size_t kMaxZerosBeforeStartCode = 8;

}  // namespace

PlaneWriter::PlaneWriter(const FrameWindow& window, int fps, const FbaEncodeOptions& options)
    : frames_(window), options_(options), fps_(fps) {
  state_.fap_quant = options.quant;
  out_.put_bits(kFbaObjectStartCode, kStartCodeBits);
  // Aligned planes each start with a plane start code, which needs stuffing before it; every
  // later one gets it from the end of the plane before (docs/mp4-and-xmta.md section 6.3).
  if (options_.align_planes) out_.put_start_code_stuffing();
  result_.header_size = out_.bit_count() / 8;
}

void PlaneWriter::write(const Gop& gop) {
  for (std::size_t k = gop.first; k < gop.end; ++k) write_plane(gop, k);
}

void PlaneWriter::write_plane(const Gop& gop, std::size_t k) {
  const bool intra = k == gop.first;
  const std::int64_t skip = k + 1 < frames_.size() ? frames_[k + 1].number - frames_[k].number - 1 : 0;
  CodedPlane plane;
  plane.bit_offset = out_.bit_count();
  plane.intra = intra;
  if (!first_number_) first_number_ = frames_[k].number;
  plane.first_frame = frames_[k].number - *first_number_;
  plane.frames = static_cast<int>(skip + 1);

  if (options_.align_planes) out_.put_bits(kFbaObjectPlaneStartCode, kStartCodeBits);
  out_.put_bit(intra ? 1 : 0);
  out_.put_bits(kObjectMaskFace, kObjectMaskBits);
  write_temporal_header(intra, skip);
  if (intra) write_intra_face_header(gop);
  write_segments(gop, k, intra);
  // A plane that would end badly grows by an empty skip count ("1 0000" for "0": 0 frames
  // skipped, the same timing), which moves its end 4 bits on. Only a plane that skips nothing
  // can; the last plane never skips.
  if (skip == 0 && needs_padding(plane.bit_offset, k + 1 == frames_.size()))
    out_.replace_bit_and_insert(skip_flag_at_, 1, 0, kSkipChunkBits);
  if (options_.align_planes) out_.put_start_code_stuffing();

  plane.bit_size = out_.bit_count() - plane.bit_offset;
  plane.offset = plane.bit_offset / 8;
  plane.size = (plane.bit_offset + plane.bit_size + 7) / 8 - plane.offset;
  result_.planes.push_back(plane);
}

void PlaneWriter::write_temporal_header(bool intra, std::int64_t skip) {
  if (intra) {
    // The frame rate goes into every intra plane, so decoding can start at any of them.
    out_.put_bit(1);  // is_frame_rate
    out_.put_bits(static_cast<std::uint32_t>(fps_), kFrameRateBits);
    out_.put_bits(0, kFrameRateSecondsBits);
    out_.put_bit(0);  // frequency_offset
    out_.put_bit(0);  // is_time_code
  }
  skip_flag_at_ = out_.bit_count();
  out_.put_bit(skip > 0 ? 1 : 0);
  if (skip == 0) return;
  for (; skip >= kSkipChunkContinues; skip -= kSkipChunkContinues) out_.put_bits(kSkipChunkContinues, kSkipChunkBits);
  out_.put_bits(static_cast<std::uint32_t>(skip), kSkipChunkBits);
}

void PlaneWriter::write_intra_face_header(const Gop& gop) {
  out_.put_bits(static_cast<std::uint32_t>(options_.quant), kFapQuantBits);
  for (const FapGroup& group : fap_groups()) {
    int masked = 0;
    for (int fap = group.first_fap; fap <= group.last_fap; ++fap) masked += gop.mask.test(FaceState::index(fap));
    const int size = group.last_fap - group.first_fap + 1;
    out_.put_bit(1);  // marker
    // Whole or empty groups need no mask bits.
    const MaskType type = options_.list_every_mask ? kMaskListed
                          : masked == 0            ? kMaskNone
                          : masked == size         ? kMaskAll
                                                   : kMaskListed;
    out_.put_bits(type, kMaskTypeBits);
    if (type == kMaskListed)
      for (int fap = group.first_fap; fap <= group.last_fap; ++fap) out_.put_bit(gop.mask.test(FaceState::index(fap)));
  }
  out_.put_bit(0);  // fba_suggested_gender, as the reference writes it
  out_.put_bit(0);  // fba_object_coding_type: predictive arithmetic coding
  // All four range lists in every intra plane (docs/fba-bitstream.md section 5.6, E9): the
  // reference decoder falls back to defaults the encoder does not share, and keeps stale ranges
  // across a fap_quant change.
  for (int list = 0; list < kRangeListCount; ++list) out_.put_bit(1);
  state_.mask = gop.mask;
  for (int list = 0; list < kRangeListCount; ++list) {
    for (const FapGroup& group : fap_groups()) {
      for (int fap = std::max(group.first_fap, kFirstLowLevelFap); fap <= group.last_fap; ++fap) {
        if ((fap - std::max(group.first_fap, kFirstLowLevelFap)) % kMarkerEvery == 0) out_.put_bit(1);
        if (!gop.mask.test(FaceState::index(fap))) continue;
        const int code = gop.codes[static_cast<std::size_t>(list)][FaceState::index(fap)];
        out_.put_bits(static_cast<std::uint32_t>(code), kRangeValueBits);
        state_.set_range(static_cast<RangeList>(list), fap, code);
      }
    }
  }
  state_.reset_models();
}

void PlaneWriter::write_segments(const Gop& gop, std::size_t k, bool intra) {
  const FrameWindow::View frame = frames_[k];
  const std::size_t row = k - gop.first;
  const std::int16_t* fields = gop.fields.data() + row * kCodedFieldCount;
  const auto code_field = [&](int field) {
    const int limit = state_.field_limit(field);
    const int q = fields[field];
    if (intra) {
      coder_.encode_uniform(limit + 1, q);
    } else {
      AdaptiveModel& model = state_.field_pred_models[static_cast<std::size_t>(field)];
      coder_.encode(model, q + limit);
      model.update(q + limit);
    }
  };
  if (frame.has(1)) {
    for (int field = 0; field < kVisemeFields; ++field) code_field(field);
    coder_.flush();
    out_.put_bit(frame.viseme.def);
  }
  if (frame.has(2)) {
    for (int field = kVisemeFields; field < kCodedFieldCount; ++field) code_field(field);
    coder_.flush();
    out_.put_bit(frame.expression.init_face);
    out_.put_bit(frame.expression.def);
  }
  const std::size_t n = gop.faps.size();
  const std::int16_t* symbols = gop.symbols.data() + row * n;
  for (std::size_t j = 0; j < n; ++j) {
    const int fap = gop.faps[j];
    if (intra) {
      const int low = state_.intra_min(fap);
      coder_.encode_uniform(state_.intra_max(fap) - low + 1, symbols[j] - low);
    } else {
      AdaptiveModel& model = state_.pred_models[FaceState::index(fap)];
      const int s = symbols[j] - state_.pred_min(fap);
      coder_.encode(model, s);
      model.update(s);
    }
  }
  coder_.flush();  // the low-level segment is always present, even with no FAP 3..68 masked
}

bool PlaneWriter::needs_padding(std::size_t start, bool last) const {
  const std::size_t end = out_.bit_count();
  // Stuffing before a start code (a plane start code when planes are aligned, else the end
  // code after the last plane) is a single '0' when one bit of the byte is left: the plane's
  // trailing zeros then run straight into the start code.
  if ((options_.align_planes || last) && end % 8 == 7 &&
      out_.trailing_zero_bits(kMaxZerosBeforeStartCode) + 1 > kMaxZerosBeforeStartCode)
    return true;
  // After each plane the reference decoder looks for the end code at the next byte boundary,
  // a whole byte on when already aligned (section 5.9). A last plane that ends before that
  // boundary, stuffing and end code filling the rest of the byte, is taken for the stuffing and
  // never decoded. Aligned planes start with a start code, which that look never skips.
  return last && !options_.align_planes && end < start / 8 * 8 + 8;
}

EncodedFba PlaneWriter::finish() {
  // Aligned planes (and the aligned header) already end with stuffing.
  if (!options_.align_planes) out_.put_start_code_stuffing();
  out_.put_bits(kVisualObjectSequenceEndCode, kStartCodeBits);
  result_.bytes = out_.take();
  return std::move(result_);
}

}  // namespace fapc::fba
