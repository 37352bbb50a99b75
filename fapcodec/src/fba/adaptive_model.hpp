// The frequency model of the FBA arithmetic coder (fba-bitstream.md sections 6.1, 6.2): an
// alphabet of n symbols with cumulative counts that DEcrease, so symbol j owns [cum[j+1], cum[j])
// and higher symbols sit lower in the interval. Every count starts at 1; after each coded symbol
// the symbol's count grows by one, and all counts are halved (rounding up) when the total has
// reached 16383. Encoder and decoder update at exactly the same points. Private to fapcodec.
//
// Speed: the counts are 16-bit (they stay below 2^15) and are searched and incremented eight at a
// time with GCC/Clang vector extensions (SSE2 on x86-64, NEON on ARM), padded to whole vectors.
#pragma once

#include <cstdint>
#include <cstring>
#include <vector>

namespace fapc::fba {

inline constexpr std::int32_t kCoderTop = 65535;
inline constexpr std::int32_t kCoderQ1 = 16384;
inline constexpr std::int32_t kCoderHalf = 32768;
inline constexpr std::int32_t kCoderQ3 = 49152;
inline constexpr std::int32_t kMaxFrequency = 16383;  // the rescale trigger
// The largest alphabet the bitstream can ask for: a range of -1860..1860 quantised units.
inline constexpr int kMaxSymbols = 2 * 1860 + 1;

class AdaptiveModel {
 public:
  // n symbols (1..kMaxSymbols), every frequency 1: cum[j] = n - j.
  void reset(int symbols);

  int symbols() const { return symbols_; }
  std::int32_t total() const { return cum_[0]; }
  std::int32_t cum(int j) const { return cum_[static_cast<std::size_t>(j)]; }

  // The symbol s with cum[s+1] <= target < cum[s], for 0 <= target < total(). Since cum
  // decreases, s + 1 is the number of k >= 0 with cum[k] > target. Counted in two steps: over
  // the heads of the blocks of 8 counts, which gives the block holding s (every count before it
  // is above the target, every one after it is not), then inside that block. Large alphabets
  // use binary search (the reference scans linearly, which makes wide ranges slow, D4).
  int find(std::int32_t target) const {
    if (symbols_ > kVectorSearchLimit) return binary_search(target);
    const Lanes threshold = splat(static_cast<std::int16_t>(target));
    Lanes above = {};
    // Padding is 0, never above a target >= 0; cum[0] is always above.
    for (std::size_t b = 0; b < heads_.size(); b += kLanes) above -= load(heads_, b) > threshold;
    const auto block = static_cast<std::size_t>(lane_sum(above) - 1) * kLanes;
    return static_cast<int>(block) + lane_sum(Lanes{} - (load(cum_, block) > threshold)) - 1;
  }

  // After coding symbol s: rescale if the total has reached kMaxFrequency, then count s:
  // cum[0..s] += 1 (and the heads of those blocks), whole vectors with later lanes masked off.
  void update(int s) {
    if (cum_[0] == kMaxFrequency) rescale();
    increment_prefix(cum_, static_cast<std::size_t>(s));
    increment_prefix(heads_, static_cast<std::size_t>(s) / kLanes);
  }

 private:
  static constexpr std::size_t kLanes = 8;
  static constexpr int kVectorSearchLimit = 1024;
  typedef std::int16_t Lanes __attribute__((vector_size(16)));

  static Lanes splat(std::int16_t v) { return Lanes{v, v, v, v, v, v, v, v}; }
  // The sum of the eight lanes (each small and non-negative), added as 16-bit fields of two
  // 64-bit words.
  static int lane_sum(Lanes v) {
    std::uint64_t half[2];
    std::memcpy(half, &v, sizeof half);
    std::uint64_t sum = half[0] + half[1];
    sum += sum >> 32;
    sum += sum >> 16;
    return static_cast<int>(sum & 0xFFFF);
  }
  static Lanes load(const std::vector<std::int16_t>& v, std::size_t j) {
    Lanes lanes;
    std::memcpy(&lanes, v.data() + j, sizeof lanes);
    return lanes;
  }
  // v[0..last] += 1.
  static void increment_prefix(std::vector<std::int16_t>& v, std::size_t last) {
    static constexpr Lanes kLane = {0, 1, 2, 3, 4, 5, 6, 7};
    const Lanes limit = splat(static_cast<std::int16_t>(last));
    for (std::size_t j = 0; j <= last; j += kLanes) {
      const Lanes lanes = load(v, j) - (kLane + splat(static_cast<std::int16_t>(j)) <= limit);  // true is -1
      std::memcpy(v.data() + j, &lanes, sizeof lanes);
    }
  }
  static std::size_t round_up(std::size_t n) { return (n + kLanes - 1) / kLanes * kLanes; }
  void copy_heads();
  int binary_search(std::int32_t target) const;
  void rescale();

  int symbols_ = 0;
  std::vector<std::int16_t> cum_;    // n + 1 entries then zeros to a whole number of vectors
  std::vector<std::int16_t> heads_;  // heads_[b] = cum_[8 b], then zeros likewise
};

}  // namespace fapc::fba
