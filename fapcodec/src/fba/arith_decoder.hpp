// The decoder half of the FBA arithmetic coder (fba-bitstream.md sections 6.4 to 6.6). It reads
// 16 bits ahead; at the end of a segment it puts the reader back just after the encoder's flush
// bits, robustly: it remembers where each of the last 16 coded bits ended in the raw stream and
// returns to the end of coded bit L - 14 (L = coded bits read), so a stuffing bit inside the
// look-ahead cannot desynchronise it (the reference's fixed 14-bit step back can, D9).
// Private to fapcodec.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "fba/adaptive_model.hpp"
#include "fba/bit_reader.hpp"

namespace fapc::fba {

class ArithDecoder {
 public:
  explicit ArithDecoder(BitReader& in) : in_(in) {}

  // decoder_reset(): fresh registers, then 16 coded bits into `code`.
  void start();

  int decode(const AdaptiveModel& model) {
    const std::int32_t t = target(model.total());
    const int s = model.find(t);
    narrow(model.cum(s), model.cum(s + 1), model.total());
    return s;
  }
  int decode_uniform(int symbols) {
    const std::int32_t t = target(symbols);
    const int s = symbols - t - 1;  // cum[k] = n - k
    narrow(symbols - s, symbols - s - 1, symbols);
    return s;
  }

  // Ends the segment: the reader moves back to just after the encoder's flush bits. Returns false
  // when the segment's own bits (not the look-ahead) hold 23 zeros in a row, which no encoder
  // produces; bad_bit_position() then says where, in raw bits.
  bool finish();
  std::size_t bad_bit_position() const { return bad_position_; }

 private:
  // code stays inside [low, high] for any input bits (t < cum[s] bounds code from above, cum[s+1]
  // <= t from below, and renormalising doubles all three), so 0 <= t < total always holds.
  std::int32_t target(std::int32_t total) const {
    const std::int32_t length = high_ - low_ + 1;
    return ((code_ - low_ + 1) * total - 1) / length;
  }
  void narrow(std::int32_t high_count, std::int32_t low_count, std::int32_t total) {
    const std::int32_t length = high_ - low_ + 1;
    high_ = low_ - 1 + (length * high_count) / total;
    low_ = low_ + (length * low_count) / total;
    for (;;) {
      if (high_ < kCoderHalf) {
        // nothing to subtract
      } else if (low_ >= kCoderHalf) {
        code_ -= kCoderHalf;
        low_ -= kCoderHalf;
        high_ -= kCoderHalf;
      } else if (low_ >= kCoderQ1 && high_ < kCoderQ3) {
        code_ -= kCoderQ1;
        low_ -= kCoderQ1;
        high_ -= kCoderQ1;
      } else {
        break;
      }
      low_ = 2 * low_;
      high_ = 2 * high_ + 1;
      code_ = 2 * code_ + get_coded_bit();
    }
  }
  int get_coded_bit() {
    int bit = in_.read_bit();
    if (zero_run_ == kStuffAfterZeros) {
      if (bit == 1) {
        bit = in_.read_bit();  // that was a stuffing bit: the run starts again
        zero_run_ = 0;
      } else {
        // 23 zeros: legal only in the look-ahead past the flush, which is judged in finish().
        if (bad_coded_bit_ == 0) {
          bad_coded_bit_ = coded_bits_ + 1;
          bad_position_ = in_.position();
        }
      }
    }
    zero_run_ = bit == 0 ? zero_run_ + 1 : 0;
    ++coded_bits_;
    coded_bit_ends_[coded_bits_ & 15] = in_.position();
    return bit;
  }
  static constexpr int kStuffAfterZeros = 22;
  static constexpr int kLookAheadBits = 14;

  BitReader& in_;
  std::int32_t low_ = 0;
  std::int32_t high_ = kCoderTop;
  std::int32_t code_ = 0;
  int zero_run_ = 0;
  std::uint64_t coded_bits_ = 0;  // L: coded bits read in this segment
  std::array<std::size_t, 16> coded_bit_ends_{};
  std::uint64_t bad_coded_bit_ = 0;  // first coded bit that broke a rule (1-based), 0 if none
  std::size_t bad_position_ = 0;
};

}  // namespace fapc::fba
