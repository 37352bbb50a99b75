// The arithmetic coder alone (docs/fba-bitstream.md section 6): random symbol streams with random
// models round-trip, segments end where the encoder's flush ended at every length, and the
// stuffing rule holds around runs of zeros.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "fba/arith_decoder.hpp"
#include "fba/arith_encoder.hpp"
#include "fba/reciprocal.hpp"

namespace fapc::fba {
namespace {

// One coded symbol: which model codes it (or a uniform one of `uniform` symbols when >= 1).
struct Coded {
  int model = -1;
  int uniform = 0;
  int symbol = 0;
};

// A segment: symbols, then a raw fixed-length field that must be found right after the flush.
struct Segment {
  std::vector<Coded> symbols;
  std::uint32_t trailer = 0;
  int trailer_bits = 0;
};

std::vector<std::uint8_t> encode_segments(const std::vector<Segment>& segments, std::vector<AdaptiveModel> models) {
  BitWriter out;
  ArithEncoder coder(out);
  for (const Segment& segment : segments) {
    for (const Coded& c : segment.symbols) {
      if (c.model < 0) {
        coder.encode_uniform(c.uniform, c.symbol);
      } else {
        coder.encode(models[c.model], c.symbol);
        models[c.model].update(c.symbol);
      }
    }
    coder.flush();
    out.put_bits(segment.trailer, segment.trailer_bits);
  }
  return out.take();
}

// Decodes and compares; returns the number of failures (reported through gtest as well).
void expect_decodes(const std::vector<std::uint8_t>& bytes, const std::vector<Segment>& segments,
                    std::vector<AdaptiveModel> models, std::size_t expected_bits) {
  BitReader in(bytes);
  ArithDecoder coder(in);
  for (std::size_t k = 0; k < segments.size(); ++k) {
    const Segment& segment = segments[k];
    coder.start();
    for (std::size_t i = 0; i < segment.symbols.size(); ++i) {
      const Coded& c = segment.symbols[i];
      int s;
      if (c.model < 0) {
        s = coder.decode_uniform(c.uniform);
      } else {
        s = coder.decode(models[c.model]);
        models[c.model].update(s);
      }
      ASSERT_EQ(s, c.symbol) << "segment " << k << " symbol " << i;
    }
    ASSERT_TRUE(coder.finish()) << "segment " << k;
    ASSERT_EQ(in.read_bits(segment.trailer_bits), segment.trailer) << "segment " << k;
  }
  EXPECT_EQ(in.position(), expected_bits);
}

std::size_t bits_of(const std::vector<Segment>& segments, std::vector<AdaptiveModel> models) {
  BitWriter out;
  ArithEncoder coder(out);
  for (const Segment& segment : segments) {
    for (const Coded& c : segment.symbols) {
      if (c.model < 0) {
        coder.encode_uniform(c.uniform, c.symbol);
      } else {
        coder.encode(models[c.model], c.symbol);
        models[c.model].update(c.symbol);
      }
    }
    coder.flush();
    out.put_bits(segment.trailer, segment.trailer_bits);
  }
  return out.bit_count();
}

int longest_zero_run(const std::vector<std::uint8_t>& bytes, std::size_t from_bit, std::size_t to_bit) {
  int run = 0, longest = 0;
  for (std::size_t b = from_bit; b < to_bit; ++b) {
    const int bit = (bytes[b / 8] >> (7 - b % 8)) & 1;
    run = bit ? 0 : run + 1;
    longest = std::max(longest, run);
  }
  return longest;
}

TEST(AdaptiveModel, StartsFlatAndCountsEachSymbol) {
  AdaptiveModel m;
  m.reset(5);
  EXPECT_EQ(m.total(), 5);
  for (int j = 0; j <= 5; ++j) EXPECT_EQ(m.cum(j), 5 - j);
  m.update(2);  // cum[0..2] grow by one
  EXPECT_EQ(m.cum(0), 6);
  EXPECT_EQ(m.cum(2), 4);
  EXPECT_EQ(m.cum(3), 2);
  EXPECT_EQ(m.find(3), 2);  // symbol 2 owns [cum[3], cum[2]) = [2, 4)
  EXPECT_EQ(m.find(2), 2);
  EXPECT_EQ(m.find(1), 3);
  EXPECT_EQ(m.find(5), 0);
}

TEST(AdaptiveModel, HalvesRoundingUpWhenTheTotalReachesTheLimit) {
  AdaptiveModel m;
  m.reset(3);
  // Frequencies 1, 1, 1 -> symbol 1 gets every count until the total is 16383.
  for (int i = 0; i < kMaxFrequency - 3; ++i) m.update(1);
  ASSERT_EQ(m.total(), kMaxFrequency);
  m.update(0);  // rescale first: (1+1)/2, (16381+1)/2, (1+1)/2 = 1, 8191, 1; then symbol 0 + 1
  EXPECT_EQ(m.cum(3), 0);
  EXPECT_EQ(m.cum(2), 1);
  EXPECT_EQ(m.cum(1), 8192);
  EXPECT_EQ(m.cum(0), 8194);
}

TEST(AdaptiveModel, UpdatesAcrossWholeVectorsLeaveLaterCountsAlone) {
  // 20 symbols: cum spans three vectors of eight; counting symbol 9 touches cum[0..9] only.
  AdaptiveModel m;
  m.reset(20);
  m.update(9);
  for (int j = 0; j <= 9; ++j) EXPECT_EQ(m.cum(j), 21 - j) << j;
  for (int j = 10; j <= 20; ++j) EXPECT_EQ(m.cum(j), 20 - j) << j;
  for (int t = 0; t < m.total(); ++t) {
    const int s = m.find(t);
    EXPECT_TRUE(m.cum(s + 1) <= t && t < m.cum(s)) << t;
  }
}

TEST(AdaptiveModel, KeepsTheCountsOfAPlainListOfFrequencies) {
  // A second implementation, as section 6.2 states the model: one count per symbol, all 1 at
  // first, cum[j] the sum from j up, halved rounding up when the total has reached 16383. Random
  // alphabets (odd and even, one symbol, the widest), symbols crowded round the middle or
  // anywhere, long enough to rescale several times; every cum, the total and find compared.
  std::mt19937 rng(23);
  for (const int n : {1, 2, 3, 7, 8, 9, 16, 17, 121, 181, 361, 1081, kMaxSymbols}) {
    for (const bool crowded : {true, false}) {
      AdaptiveModel m;
      m.reset(n);
      std::vector<std::int32_t> counts(static_cast<std::size_t>(n), 1);
      const auto cum = [&](int j) {
        std::int32_t sum = 0;
        for (int i = j; i < n; ++i) sum += counts[static_cast<std::size_t>(i)];
        return sum;
      };
      for (int step = 0; step < 40000; ++step) {
        int s = static_cast<int>(rng() % static_cast<unsigned>(n));
        if (crowded) s = std::clamp(n / 2 + static_cast<int>(rng() % 7) - 3, 0, n - 1);
        if (n > 1) {
          if (cum(0) == kMaxFrequency)
            for (std::int32_t& c : counts) c = (c + 1) / 2;
          ++counts[static_cast<std::size_t>(s)];
        }
        m.update(s);
        if (step % 997 != 0 && step < 39990) continue;
        ASSERT_EQ(m.total(), cum(0)) << n << " step " << step;
        for (int j = 0; j <= n; ++j) ASSERT_EQ(m.cum(j), cum(j)) << n << " cum " << j << " step " << step;
        for (std::int32_t t = 0; t < m.total(); t += 1 + static_cast<std::int32_t>(rng() % 37)) {
          const int found = m.find(t);
          ASSERT_TRUE(cum(found + 1) <= t && t < cum(found)) << n << " target " << t;
        }
      }
    }
  }
}

TEST(Reciprocal, DividesLikeTheDivideInstructionForEveryTotal) {
  // Checked against the compiler's division: every divisor, numerators at and around each of
  // its multiples up to the largest the coder forms, plus random ones.
  std::mt19937 rng(17);
  for (std::int32_t d = 1; d <= kMaxFrequency; ++d) {
    const std::int32_t largest = (1 << 30) - 1;
    for (const std::int32_t n : {0, 1, d - 1, d, d + 1, 65536 * d - 1, 65536 * d, largest - 1, largest})
      ASSERT_EQ(divide_by_total(n, d), n / d) << n << " / " << d;
    for (int i = 0; i < 8; ++i) {
      const auto n = static_cast<std::int32_t>(rng() % (1u << 30));
      ASSERT_EQ(divide_by_total(n, d), n / d) << n << " / " << d;
    }
  }
}

TEST(ArithCoder, EmptySegmentCostsTheTwoBitsZeroOne) {
  BitWriter out;
  ArithEncoder coder(out);
  coder.flush();
  EXPECT_EQ(out.bit_count(), 2u);
  EXPECT_EQ(out.take(), std::vector<std::uint8_t>{0x40});
}

TEST(ArithCoder, RandomStreamsWithRandomModelsRoundTrip) {
  std::mt19937 rng(4);
  for (int trial = 0; trial < 300; ++trial) {
    const int model_count = 1 + static_cast<int>(rng() % 6);
    std::vector<AdaptiveModel> models(static_cast<std::size_t>(model_count));
    for (AdaptiveModel& m : models) {
      const int sizes[] = {1, 2, 3, 15, 61, 121, 1001, kMaxSymbols};
      m.reset(sizes[rng() % 8]);
    }
    std::vector<Segment> segments(1 + rng() % 5);
    for (Segment& segment : segments) {
      const int count = static_cast<int>(rng() % 80);
      for (int i = 0; i < count; ++i) {
        Coded c;
        if (rng() % 4 == 0) {
          c.uniform = 1 + static_cast<int>(rng() % kMaxSymbols);
          c.symbol = static_cast<int>(rng() % static_cast<unsigned>(c.uniform));
        } else {
          c.model = static_cast<int>(rng() % static_cast<unsigned>(model_count));
          const int n = models[c.model].symbols();
          // Skewed choices, as real differences are: mostly near the middle.
          const int middle = n / 2, spread = 1 + static_cast<int>(rng() % 4);
          c.symbol = std::clamp(middle + static_cast<int>(rng() % (2 * spread + 1)) - spread, 0, n - 1);
          if (rng() % 10 == 0) c.symbol = static_cast<int>(rng() % static_cast<unsigned>(n));
        }
        segment.symbols.push_back(c);
      }
      segment.trailer_bits = static_cast<int>(rng() % 33);
      segment.trailer =
          segment.trailer_bits == 0 ? 0 : static_cast<std::uint32_t>(rng()) >> (32 - segment.trailer_bits);
    }
    const auto bytes = encode_segments(segments, models);
    expect_decodes(bytes, segments, models, bits_of(segments, models));
    if (testing::Test::HasFatalFailure()) FAIL() << "trial " << trial;
  }
}

TEST(ArithCoder, LongAdaptiveRunThroughRescalingRoundTrips) {
  std::mt19937 rng(7);
  std::vector<AdaptiveModel> models(2);
  models[0].reset(121);
  models[1].reset(7);
  Segment segment;
  for (int i = 0; i < 40000; ++i) {
    const int model = i % 3 == 0 ? 1 : 0;
    const int n = models[model].symbols();
    segment.symbols.push_back({model, 0, std::clamp(n / 2 + static_cast<int>(rng() % 5) - 2, 0, n - 1)});
  }
  segment.trailer = 0x2A5;
  segment.trailer_bits = 10;
  const std::vector<Segment> segments{segment};
  expect_decodes(encode_segments(segments, models), segments, models, bits_of(segments, models));
}

// After every number of symbols from 0 to 400 the decoder lands exactly after the flush, with
// each possible trailer of ones and zeros (the trailer is read back by the test).
TEST(ArithCoder, TerminatesExactlyAtEveryLength) {
  std::mt19937 rng(11);
  std::vector<Coded> pool;
  std::vector<AdaptiveModel> models(1);
  models[0].reset(61);
  for (int i = 0; i < 400; ++i) {
    if (i % 5 == 0) {
      const int n = 1 + static_cast<int>(rng() % 300);
      pool.push_back({-1, n, static_cast<int>(rng() % static_cast<unsigned>(n))});
    } else {
      pool.push_back({0, 0, 25 + static_cast<int>(rng() % 10)});
    }
  }
  for (std::size_t length = 0; length <= pool.size(); ++length) {
    for (const std::uint32_t trailer : {0x00000000u, 0xFFFFFFFFu, 0x80000001u}) {
      Segment segment{std::vector<Coded>(pool.begin(), pool.begin() + static_cast<long>(length)), trailer, 32};
      const std::vector<Segment> segments{segment, segment};
      expect_decodes(encode_segments(segments, models), segments, models, bits_of(segments, models));
      if (testing::Test::HasFatalFailure()) FAIL() << "length " << length;
    }
  }
}

// A uniform model of 2 symbols codes symbol 1 in the lower half: every such symbol is a '0' of
// output, so long runs must be broken by stuffing bits, and the decoder must remove them.
TEST(ArithCoder, StuffsAOneAfter22ZerosAndTheDecoderRemovesIt) {
  for (int zeros = 1; zeros <= 70; ++zeros) {
    Segment segment;
    for (int i = 0; i < zeros; ++i) segment.symbols.push_back({-1, 2, 1});
    segment.symbols.push_back({-1, 2, 0});
    // A trailer of zeros after the flush extends the run past 22 in the look-ahead, the edge case
    // where the reference's fixed rewind goes wrong (D9); ones after it end the stream.
    segment.trailer = 0x0000FFFF;
    segment.trailer_bits = 32;
    const std::vector<Segment> segments{segment, segment};
    const std::vector<AdaptiveModel> no_models;
    const auto bytes = encode_segments(segments, no_models);
    const std::size_t bits = bits_of(segments, no_models);
    // Inside the segments no 23 zeros (the stuffing bit breaks each run of 22).
    Segment bare = segment;
    bare.trailer_bits = 0;
    const std::size_t segment_bits = bits_of({bare}, no_models);
    EXPECT_LE(longest_zero_run(bytes, 0, segment_bits), 22) << zeros;
    if (zeros >= 23) {
      EXPECT_EQ(longest_zero_run(bytes, 0, segment_bits), 22) << zeros;
    }
    expect_decodes(bytes, segments, no_models, bits);
    if (testing::Test::HasFatalFailure()) FAIL() << "zeros " << zeros;
  }
}

TEST(ArithCoder, TwentyThreeZerosInsideASegmentAreReportedWithTheirPosition) {
  std::vector<std::uint8_t> bytes(16, 0x00);  // nothing but zeros: no encoder writes this
  bytes.back() = 0xFF;
  BitReader in(bytes);
  ArithDecoder coder(in);
  coder.start();
  for (int i = 0; i < 40; ++i) coder.decode_uniform(2);
  EXPECT_FALSE(coder.finish());
  EXPECT_EQ(coder.bad_bit_position(), 23u);
}

}  // namespace
}  // namespace fapc::fba
