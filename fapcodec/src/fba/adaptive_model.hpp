// The frequency model of the FBA arithmetic coder (fba-bitstream.md sections 6.1, 6.2): an
// alphabet of n symbols with cumulative counts that DEcrease, so symbol j owns [cum[j+1], cum[j])
// and higher symbols sit lower in the interval. Every count starts at 1; after each coded symbol
// the symbol's count grows by one, and all counts are halved (rounding up) when the total has
// reached 16383. Encoder and decoder update at exactly the same points. Private to fapcodec.
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

  int symbols() const { return static_cast<int>(cum_.size()) - 1; }
  std::int32_t total() const { return cum_[0]; }
  std::int32_t cum(int j) const { return cum_[static_cast<std::size_t>(j)]; }

  // The symbol s with cum[s+1] <= target < cum[s], for 0 <= target < total(). Binary search: the
  // reference scans linearly, which makes wide ranges slow (section 12.6, D4).
  int find(std::int32_t target) const {
    int lo = 1, hi = symbols();
    const std::uint16_t* c = cum_.data();
    while (lo < hi) {
      const int mid = (lo + hi) >> 1;
      if (c[mid] <= target) {
        hi = mid;
      } else {
        lo = mid + 1;
      }
    }
    return lo - 1;
  }

  // After coding symbol s: rescale if the total has reached kMaxFrequency, then count s.
  void update(int s) {
    if (cum_[0] == kMaxFrequency) rescale();
    increment_prefix(cum_.data(), s + 1);
  }

 private:
  // cum[0..count) += 1, four counts per 64-bit add (counts stay below 2^15, so lanes never carry).
  static void increment_prefix(std::uint16_t* c, int count) {
    constexpr std::uint64_t kOnes = 0x0001000100010001ull;
    int j = 0;
    for (; j + 4 <= count; j += 4) {
      std::uint64_t lanes;
      std::memcpy(&lanes, c + j, sizeof lanes);
      lanes += kOnes;
      std::memcpy(c + j, &lanes, sizeof lanes);
    }
    for (; j < count; ++j) ++c[j];
  }
  void rescale();

  std::vector<std::uint16_t> cum_;  // n + 1 entries, cum_[n] == 0
};

}  // namespace fapc::fba
