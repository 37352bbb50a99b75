#include "fba/arith_decoder.hpp"

namespace fapc::fba {

void ArithDecoder::start() {
  low_ = 0;
  high_ = kCoderTop;
  code_ = 0;
  zero_run_ = 0;
  coded_bits_ = 0;
  bad_coded_bit_ = 0;
  for (int i = 0; i < 16; ++i) code_ = 2 * code_ + get_coded_bit();
}

bool ArithDecoder::finish() {
  // The decoder has read exactly 14 coded bits more than the encoder wrote (section 6.6), and it
  // always reads at least 16, so bit L - 14 is among the 16 remembered.
  const std::uint64_t written = coded_bits_ - kLookAheadBits;
  in_.seek(coded_bit_ends_[written & 15]);
  return bad_coded_bit_ == 0 || bad_coded_bit_ > written;
}

}  // namespace fapc::fba
