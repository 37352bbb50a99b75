#include "fba/arith_decoder.hpp"

namespace fapc::fba {

void ArithDecoder::start() {
  low_ = 0;
  high_ = kCoderTop;
  zero_run_ = 0;
  segment_start_ = in_.position();
  coded_bits_ = 0;
  stuffing_after_.clear();
  bad_coded_bit_ = 0;
  Registers r = load();
  r.code = static_cast<std::int32_t>(get_coded_bits(r, 16));
  save(r);
}

int ArithDecoder::get_coded_bit() {
  int bit = in_.read_bit();
  if (zero_run_ == kStuffAfterZeros) {
    if (bit == 1) {
      stuffing_after_.push_back(coded_bits_);
      bit = in_.read_bit();  // that was a stuffing bit: the run starts again
      zero_run_ = 0;
    } else if (bad_coded_bit_ == 0) {
      // 23 zeros: legal only in the look-ahead past the flush, which is judged in finish().
      bad_coded_bit_ = coded_bits_ + 1;
      bad_position_ = in_.position();
    }
  }
  zero_run_ = bit == 0 ? zero_run_ + 1 : 0;
  ++coded_bits_;
  return bit;
}

bool ArithDecoder::finish() {
  // The decoder has read exactly 14 coded bits more than the encoder wrote (docs/fba-bitstream.md
  // section 6.6), and it always reads at least 16. Coded bit L - 14 ends after those bits and the
  // stuffing bits that came before them.
  const std::uint64_t written = coded_bits_ - kLookAheadBits;
  std::size_t stuffing = 0;
  for (const std::uint64_t after : stuffing_after_) stuffing += after < written;
  in_.seek(segment_start_ + written + stuffing);
  return bad_coded_bit_ == 0 || bad_coded_bit_ > written;
}

}  // namespace fapc::fba
