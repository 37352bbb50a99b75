// The encoder half of the FBA arithmetic coder (fba-bitstream.md sections 6.3, 6.4): 16-bit
// registers in the style of H.263 Annex E, and a stuffing '1' after 22 zeros of coder output so
// that a segment never emulates a start code. Private to fapcodec.
#pragma once

#include <cstdint>

#include "fba/adaptive_model.hpp"
#include "fba/bit_writer.hpp"

namespace fapc::fba {

class ArithEncoder {
 public:
  explicit ArithEncoder(BitWriter& out) : out_(out) {}

  // Codes the sub-interval [low_count, high_count) of `total`. Invariant between calls:
  // 0 <= low <= high <= 65535 and high - low >= 16384 (the interval straddles a quarter).
  void encode(std::int32_t high_count, std::int32_t low_count, std::int32_t total) {
    const std::int32_t length = high_ - low_ + 1;
    high_ = low_ - 1 + (length * high_count) / total;
    low_ = low_ + (length * low_count) / total;
    for (;;) {
      if (high_ < kCoderHalf) {
        emit(0);
      } else if (low_ >= kCoderHalf) {
        emit(1);
        low_ -= kCoderHalf;
        high_ -= kCoderHalf;
      } else if (low_ >= kCoderQ1 && high_ < kCoderQ3) {
        ++pending_;
        low_ -= kCoderQ1;
        high_ -= kCoderQ1;
      } else {
        break;
      }
      low_ = 2 * low_;
      high_ = 2 * high_ + 1;
    }
  }
  void encode(const AdaptiveModel& model, int symbol) {
    encode(model.cum(symbol), model.cum(symbol + 1), model.total());
  }
  // A fresh model of n symbols that is never updated (the intra models, section 6.7).
  void encode_uniform(int symbols, int symbol) {
    encode(symbols - symbol, symbols - symbol - 1, symbols);
  }

  // Ends the segment: (pending + 2) bits that pin the final interval, then a fresh state.
  void flush();

 private:
  void emit(int bit) {
    put_coded_bit(bit);
    for (; pending_ > 0; --pending_) put_coded_bit(1 - bit);
  }
  void put_coded_bit(int bit) {
    if (zero_run_ == kStuffAfterZeros) {
      out_.put_bit(1);
      zero_run_ = 0;
    }
    out_.put_bit(bit);
    zero_run_ = bit == 0 ? zero_run_ + 1 : 0;
  }

  static constexpr int kStuffAfterZeros = 22;

  BitWriter& out_;
  std::int32_t low_ = 0;
  std::int32_t high_ = kCoderTop;
  std::int32_t pending_ = 0;  // bits to follow with the opposite value
  int zero_run_ = 0;
};

}  // namespace fapc::fba
