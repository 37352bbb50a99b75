// The decoder half of the FBA arithmetic coder (docs/fba-bitstream.md sections 6.4 to 6.6). It
// reads 16 bits ahead; at the end of a segment it puts the reader back just after the encoder's
// flush bits, robustly: it knows where every stuffing bit of the segment was, so it returns to the
// end of coded bit L - 14 (L = coded bits read) even when a stuffing bit lies inside the look-ahead
// (the reference's fixed 14-bit step back cannot, D9). Private to fapcodec.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "fba/adaptive_model.hpp"
#include "fba/bit_reader.hpp"
#include "fba/reciprocal.hpp"

namespace fapc::fba {

class ArithDecoder {
 public:
  explicit ArithDecoder(BitReader& in) : in_(in) {}

  // decoder_reset(): fresh registers, then 16 coded bits into `code`.
  void start();

  // A one-symbol alphabet (a FAP whose range is 0..0) leaves the interval as it is and takes no
  // bits: such symbols are skipped outright, on both sides.
  int decode(const AdaptiveModel& model) {
    Registers r = load();
    const int s = decode(r, model);
    save(r);
    return s;
  }
  int decode_uniform(int symbols) {
    Registers r = load();
    const int s = decode_uniform(r, symbols);
    save(r);
    return s;
  }
  // For each index i of `which` in turn: decodes a symbol with models[i], counts it there, and
  // hands it to visit(i, symbol). The same as decode() then update() for each, but the coder's
  // registers stay in processor registers for the whole run: kept in the object, they are stored
  // and loaded again around every symbol (the compiler cannot tell that the caller's stores of
  // decoded values leave them alone), on the chain of operations every symbol waits for.
  template <class Visit>
  void decode_and_count(std::span<const std::uint8_t> which, std::span<AdaptiveModel> models, Visit visit) {
    Registers r = load();
    for (const std::uint8_t i : which) {
      AdaptiveModel& model = models[i];
      const int s = decode(r, model);
      model.update(s);
      visit(i, s);
    }
    save(r);
  }

  // Ends the segment: the reader moves back to just after the encoder's flush bits. Returns false
  // when the segment's own bits (not the look-ahead) hold 23 zeros in a row, which no encoder
  // produces; bad_bit_position() then says where, in raw bits.
  bool finish();
  std::size_t bad_bit_position() const { return bad_position_; }

 private:
  // What every symbol reads and changes: the coder's state and the reader's position, copied
  // into a local for the length of a call or a run.
  struct Registers {
    std::int32_t low;
    std::int32_t high;
    std::int32_t code;
    int zero_run;
    std::uint64_t coded_bits;
    std::size_t position;
  };
  Registers load() const { return {low_, high_, code_, zero_run_, coded_bits_, in_.position()}; }
  void save(const Registers& r) {
    low_ = r.low;
    high_ = r.high;
    code_ = r.code;
    zero_run_ = r.zero_run;
    coded_bits_ = r.coded_bits;
    in_.seek(r.position);
  }

  int decode(Registers& r, const AdaptiveModel& model) {
    if (model.symbols() == 1) return 0;
    // The target ((code - low + 1) * total - 1) / length of section 6.5, found without dividing.
    const int s = model.find_scaled((r.code - r.low + 1) * model.total(), r.high - r.low + 1);
    narrow(r, model.cum(s), model.cum(s + 1), model.total());
    return s;
  }
  int decode_uniform(Registers& r, int symbols) {
    if (symbols == 1) return 0;
    // code stays inside [low, high] for any input bits (t < cum[s] bounds code from above,
    // cum[s+1] <= t from below, and renormalising maps all three alike), so 0 <= t < total.
    const std::int32_t t = ((r.code - r.low + 1) * symbols - 1) / (r.high - r.low + 1);
    const int s = symbols - t - 1;  // cum[k] = n - k
    narrow(r, symbols - s, symbols - s - 1, symbols);
    return s;
  }
  // The interval of the decoded symbol, then renormalisation (section 6.5) done in two strides
  // rather than bit by bit. While low and high share their top bit, each step drops it: that is
  // `a` steps, the run of equal leading bits. After those, low starts 0 and high 1, so only the
  // middle-half step can follow, which drops bit 14 of each while low has it 1 and high 0: `b`
  // steps. No step of the first kind can follow one of the second. `code` goes through the same
  // steps, taking in one coded bit per step: a + b bits, read at once.
  void narrow(Registers& r, std::int32_t high_count, std::int32_t low_count, std::int32_t total) {
    const std::int32_t length = r.high - r.low + 1;
    auto high = static_cast<std::uint32_t>(r.low - 1 + divide_by_total(length * high_count, total));
    auto low = static_cast<std::uint32_t>(r.low + divide_by_total(length * low_count, total));
    const int a = std::countl_zero(static_cast<std::uint16_t>(low ^ high));
    low = (low << a) & 0xFFFF;
    high = ((high << a) | ((1u << a) - 1)) & 0xFFFF;
    const int b = std::countl_one(static_cast<std::uint16_t>((low & ~high) << 1));
    const std::int32_t scale = 1 << b;
    r.low = (static_cast<std::int32_t>(low) - kCoderHalf) * scale + kCoderHalf;
    r.high = (static_cast<std::int32_t>(high) - kCoderHalf) * scale + kCoderHalf + scale - 1;
    const std::uint32_t bits = get_coded_bits(r, a + b);
    const auto code = static_cast<std::int32_t>(((static_cast<std::uint32_t>(r.code) << a) | (bits >> b)) & 0xFFFF);
    r.code = (code - kCoderHalf) * scale + kCoderHalf +
             static_cast<std::int32_t>(bits & static_cast<std::uint32_t>(scale - 1));
  }
  // `count` (0..31) coded bits as a number, first bit highest, stuffing bits removed.
  std::uint32_t get_coded_bits(Registers& r, int count) {
    // A stuffing bit can only come where 22 zeros precede it; short of that, the raw bits are
    // the coded bits.
    if (r.zero_run + count <= kStuffAfterZeros) {
      const std::uint32_t bits = in_.peek_bits_at(r.position, count);
      r.position += static_cast<std::size_t>(count);
      r.zero_run = bits == 0 ? r.zero_run + count : std::countr_zero(bits);
      r.coded_bits += static_cast<std::uint64_t>(count);
      return bits;
    }
    save(r);
    std::uint32_t bits = 0;
    for (int i = 0; i < count; ++i) bits = (bits << 1) | static_cast<std::uint32_t>(get_coded_bit());
    r = load();
    return bits;
  }
  int get_coded_bit();

  static constexpr int kStuffAfterZeros = 22;
  static constexpr int kLookAheadBits = 14;

  BitReader& in_;
  std::int32_t low_ = 0;
  std::int32_t high_ = kCoderTop;
  std::int32_t code_ = 0;
  int zero_run_ = 0;
  std::size_t segment_start_ = 0;  // raw bit position of the segment's first bit
  std::uint64_t coded_bits_ = 0;   // L: coded bits read in this segment
  // For each stuffing bit removed in this segment, how many coded bits came before it.
  std::vector<std::uint64_t> stuffing_after_;
  std::uint64_t bad_coded_bit_ = 0;  // first coded bit that broke a rule (1-based), 0 if none
  std::size_t bad_position_ = 0;
};

}  // namespace fapc::fba
