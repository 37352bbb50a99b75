// The encoder half of the FBA arithmetic coder (docs/fba-bitstream.md sections 6.3, 6.4): 16-bit
// registers in the style of H.263 Annex E, and a stuffing '1' after 22 zeros of coder output so
// that a segment never emulates a start code. Private to fapcodec.
#pragma once

#include <algorithm>
#include <bit>
#include <cstdint>

#include "fba/adaptive_model.hpp"
#include "fba/bit_writer.hpp"
#include "fba/reciprocal.hpp"

namespace fapc::fba {

class ArithEncoder {
 public:
  explicit ArithEncoder(BitWriter& out) : out_(out) {}

  // Codes the sub-interval [low_count, high_count) of `total`. Invariant between calls:
  // 0 <= low <= high <= 65535 and high - low >= 16384 (the interval straddles a quarter).
  // Renormalisation goes in two strides, as in the decoder (arith_decoder.hpp): first the `a`
  // leading bits low and high share, which go out (the first of them followed by the pending
  // opposite bits), then `b` middle-half steps, which only add to the pending count. Either may be
  // 0; both are taken without a branch (which bits a symbol sends is as good as random, so a
  // branch on them is mispredicted half of the time), and the bits go out in one piece.
  void encode(std::int32_t high_count, std::int32_t low_count, std::int32_t total) {
    const std::int32_t length = high_ - low_ + 1;
    const std::int32_t high = low_ - 1 + divide_by_total(length * high_count, total);
    const std::int32_t low = low_ + divide_by_total(length * low_count, total);
    const int a = std::countl_zero(static_cast<std::uint16_t>(low ^ high));
    // The a shared bits: the first (the top bit of low), the pending opposite bits, the other a - 1.
    const auto ulow = static_cast<std::uint32_t>(low);
    const bool sends = a > 0;
    const int rest = sends ? a - 1 : 0;
    const std::uint32_t first = sends ? ulow >> 15 : 0;
    const std::uint32_t rest_bits = (ulow >> (16 - a)) & ((1u << rest) - 1);
    const int pending = sends ? pending_ : 0;
    if (pending > kMaxPendingInOnePiece) [[unlikely]] {
      emit_long(first, rest_bits, rest);
    } else {
      const std::uint64_t opposite = first ? 0 : (std::uint64_t{1} << pending) - 1;
      put_coded_bits((std::uint64_t{first} << (pending + rest)) | (opposite << rest) | rest_bits,
                     static_cast<int>(sends) + pending + rest);
      pending_ -= pending;
    }
    const std::int32_t shifted_low = static_cast<std::int32_t>((ulow << a) & 0xFFFF);
    const std::int32_t shifted_high =
        static_cast<std::int32_t>(((static_cast<std::uint32_t>(high) << a) | ((1u << a) - 1)) & 0xFFFF);
    const int b = std::countl_one(static_cast<std::uint16_t>((shifted_low & ~shifted_high) << 1));
    const std::int32_t scale = 1 << b;
    pending_ += b;
    low_ = (shifted_low - kCoderHalf) * scale + kCoderHalf;
    high_ = (shifted_high - kCoderHalf) * scale + kCoderHalf + scale - 1;
  }
  // A one-symbol alphabet leaves the interval as it is and emits nothing: skipped.
  void encode(const AdaptiveModel& model, int symbol) {
    if (model.symbols() > 1) encode(model.cum(symbol), model.cum(symbol + 1), model.total());
  }
  // A fresh model of n symbols that is never updated (the intra models, section 6.7).
  void encode_uniform(int symbols, int symbol) {
    if (symbols > 1) encode(symbols - symbol, symbols - symbol - 1, symbols);
  }

  // Ends the segment: (pending + 2) bits that pin the final interval, then a fresh state.
  void flush();

 private:
  // The most pending bits that go out with the bits around them in one piece (at most 1 + 40 +
  // 15 bits); more, which takes some 40 symbols straddling the middle, go a piece at a time.
  static constexpr int kMaxPendingInOnePiece = 40;

  // One bit, then the pending bits, all of the opposite value.
  void emit(int bit) {
    put_coded_bits(static_cast<std::uint32_t>(bit), 1);
    const std::uint32_t opposite = bit ? 0u : ~0u;
    for (; pending_ > 0; pending_ -= std::min(pending_, 16)) put_coded_bits(opposite, std::min(pending_, 16));
  }
  // emit(first), then the `count` bits of `rest`.
  void emit_long(std::uint32_t first, std::uint32_t rest, int count) {
    emit(static_cast<int>(first));
    put_coded_bits(rest, count);
  }
  // The low `count` (0..56) bits of `bits`, first bit highest, with a stuffing '1' after every 22
  // zeros (section 6.4).
  void put_coded_bits(std::uint64_t bits, int count) {
    bits &= (std::uint64_t{1} << count) - 1;
    // Short of 22 zeros in a row nothing needs stuffing (and then count <= 22).
    if (zero_run_ + count <= kStuffAfterZeros) [[likely]] {
      out_.put_bits(static_cast<std::uint32_t>(bits), count);
      zero_run_ = bits == 0 ? zero_run_ + count : std::countr_zero(bits);
      return;
    }
    for (int i = count - 1; i >= 0; --i) put_coded_bit(static_cast<int>((bits >> i) & 1));
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
