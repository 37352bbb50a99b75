// The frequency model of the FBA arithmetic coder (docs/fba-bitstream.md sections 6.1, 6.2): an
// alphabet of n symbols with cumulative counts that DEcrease, so symbol j owns [cum[j+1], cum[j])
// and higher symbols sit lower in the interval. Every count starts at 1; after each coded symbol
// the symbol's count grows by one, and all counts are halved (rounding up) when the total has
// reached 16383. Encoder and decoder update at exactly the same points. Private to fapcodec.
//
// Speed: counting symbol s raises cum[0..s], on average half the alphabet, though the symbols
// (differences of a FAP from one frame to the next) crowd around the middle of the alphabet, the
// difference 0. So the sums are kept from the middle m outwards: for j <= m the sum of the counts
// below j (cum[j] = total - that), for j > m cum[j] itself. Counting s then changes only the
// entries between s and m, a few at most, besides the total. The entries are 16-bit (they stay
// below 2^15) and change eight at a time with GCC/Clang vector extensions (SSE2 on x86-64, NEON
// on ARM), padded to whole vectors.
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
  std::int32_t total() const { return total_; }
  std::int32_t cum(int j) const { return sums_[static_cast<std::size_t>(j)] + (j <= middle_ ? total_ : 0); }

  // The symbol s with cum[s+1] <= target < cum[s], for 0 <= target < total().
  int find(std::int32_t target) const { return find_scaled(target + 1, 1); }
  // The same search for the target floor((scaled - 1) / length), without dividing: cum[k] is
  // above that target exactly when cum[k] * length >= scaled. Binary search (the reference scans
  // linearly, which makes wide ranges slow, section 12.6, D4); a plain branching search measured
  // faster here than counting a vector at a time, as the processor runs ahead on its guesses.
  // Products stay below 2^30 for lengths up to 65536.
  int find_scaled(std::int32_t scaled, std::int32_t length) const {
    const auto above = [&](int k) { return cum(k) * length >= scaled; };
    // lo is above the target, hi is not (cum[0] always is, cum[n] = 0 never): s is in [lo, hi).
    int lo, hi;
    int step = 1;
    if (above(last_)) {
      lo = last_;
      hi = last_ + 1;
      while (hi < symbols_ && above(hi)) {
        lo = hi;
        step *= 2;
        hi = lo + step < symbols_ ? lo + step : symbols_;
      }
    } else {
      hi = last_;
      lo = last_ - 1;
      while (lo > 0 && !above(lo)) {
        hi = lo;
        step *= 2;
        lo = hi - step > 0 ? hi - step : 0;
      }
    }
    while (hi - lo > 1) {
      const int mid = (lo + hi) >> 1;
      if (above(mid)) {
        lo = mid;
      } else {
        hi = mid;
      }
    }
    return lo;
  }

  // After coding symbol s: rescale if the total has reached kMaxFrequency, then count s: the
  // total, and the entries from s to the middle (below it, the sums below them grow; above it,
  // the sums above them), whole vectors with the lanes outside masked off. The counts of a
  // one-symbol alphabet never matter (its symbol always owns the whole interval), so they are
  // left alone.
  void update(int s) {
    if (symbols_ == 1) return;
    if (total_ == kMaxFrequency) rescale();
    last_ = s;
    ++total_;
    const bool below = s < middle_;
    add_to_range(below ? s + 1 : middle_ + 1, below ? middle_ : s, below ? -1 : 1);
  }

 private:
  static constexpr std::size_t kLanes = 8;
  typedef std::int16_t Lanes __attribute__((vector_size(16)));

  static Lanes load(const std::vector<std::int16_t>& v, std::size_t j) {
    Lanes lanes;
    std::memcpy(&lanes, v.data() + j, sizeof lanes);
    return lanes;
  }
  static void store(std::vector<std::int16_t>& v, std::size_t j, Lanes lanes) {
    std::memcpy(v.data() + j, &lanes, sizeof lanes);
  }
  // sums_[first..last] += delta (nothing when last < first), a vector at a time from the one
  // holding `first`.
  void add_to_range(int first, int last, int delta) {
    static constexpr Lanes kLane = {0, 1, 2, 3, 4, 5, 6, 7};
    const auto d = static_cast<std::int16_t>(delta);
    const Lanes deltas = {d, d, d, d, d, d, d, d};
    const auto low = static_cast<std::int16_t>(first), high = static_cast<std::int16_t>(last);
    for (int j = first & ~static_cast<int>(kLanes - 1); j <= last; j += static_cast<int>(kLanes)) {
      const auto base = static_cast<std::int16_t>(j);
      const Lanes index = Lanes{base, base, base, base, base, base, base, base} + kLane;
      const Lanes inside = (index >= low) & (index <= high);
      store(sums_, static_cast<std::size_t>(j), load(sums_, static_cast<std::size_t>(j)) + (deltas & inside));
    }
  }
  static std::size_t round_up(std::size_t n) { return (n + kLanes - 1) / kLanes * kLanes; }
  void rescale();

  int symbols_ = 0;
  int last_ = 0;    // the last symbol counted, where the search starts
  int middle_ = 0;  // m = n / 2
  std::int32_t total_ = 0;
  // n + 1 entries then zeros to a whole number of vectors: for j <= m minus the sum of the counts
  // below j, for j > m the sum of the counts from j up (cum[j]; 0 at j = n).
  std::vector<std::int16_t> sums_;
};

}  // namespace fapc::fba
