// The decoder on streams our encoder never writes, built field by field in the test from
// docs/fba-bitstream.md: default ranges, time codes, fractional frame rates, body data in mixed
// streams, mask type 10, legacy start codes; and on broken streams, which give an error with the
// byte offset and never crash.
#include <gtest/gtest.h>

#include <random>

#include "fapc/codec/fba.hpp"
#include "fba/arith_encoder.hpp"

namespace fapc {
namespace {

using fba::AdaptiveModel;

// Writes planes field by field. Only what the tests need: group masks listed explicitly.
struct StreamBuilder {
  fba::BitWriter out;
  fba::ArithEncoder coder{out};

  explicit StreamBuilder(std::uint32_t object_start_code = 0x000001BA) { out.put_bits(object_start_code, 32); }
  void bits(std::uint32_t value, int count) { out.put_bits(value, count); }
  // is_intra, fba_object_mask and an intra plane's temporal header without rate or time code.
  void plane(bool intra, std::uint32_t object_mask) {
    bits(intra, 1);
    bits(object_mask, 2);
  }
  // Face masks: type 01 for group 2 listing FAP 3 (and FAP 4 when asked), 00 elsewhere; or type
  // `type` for group 2 when given.
  void face_masks(std::uint32_t group2_type, bool fap4 = false, bool fap63 = false) {
    for (int group = 1; group <= 10; ++group) {
      bits(1, 1);  // marker
      if (group == 2) {
        bits(group2_type, 2);
        bits(fap4 ? 0xC000 : 0x8000, 16);
      } else if (group == 9 && fap63) {
        bits(1, 2);
        bits(0x2, 4);  // FAPs 61..64: only 63
      } else {
        bits(0, 2);
      }
    }
  }
  // One range list over FAPs 3..68 with value v for the masked ones (group 2 FAPs 3/4, group 9 FAP 63).
  void face_range_list(int v, bool fap4 = false, bool fap63 = false) {
    const int group_first[] = {3, 19, 31, 39, 43, 48, 51, 61, 65};
    const int group_last[] = {18, 30, 38, 42, 47, 50, 60, 64, 68};
    for (int g = 0; g < 9; ++g)
      for (int fap = group_first[g]; fap <= group_last[g]; ++fap) {
        if ((fap - group_first[g]) % 4 == 0) bits(1, 1);
        if (fap == 3 || (fap == 4 && fap4) || (fap == 63 && fap63)) bits(static_cast<std::uint32_t>(v), 5);
      }
  }
  std::vector<std::uint8_t> finish() {
    out.put_start_code_stuffing();
    out.put_bits(0x000001B1, 32);
    return out.take();
  }
};

Result<DecodedFba> decode(const std::vector<std::uint8_t>& bytes) {
  FbaDecodeOptions options;
  options.file = "t.fba";
  return decode_fba(bytes, options);
}

std::string error_of(const std::vector<std::uint8_t>& bytes) {
  auto decoded = decode(bytes);
  return decoded.ok() ? "decoded" : format_diagnostic(decoded.error());
}

TEST(FbaDecoder, FirstIntraPlaneWithoutListsUsesTheDefaultTable) {
  StreamBuilder b;
  b.plane(true, 1);
  b.bits(0b00, 2);  // no frame rate, no time code
  b.bits(0, 1);     // no skip
  b.bits(1, 5);     // fap_quant 1
  b.face_masks(1, false, true);
  b.bits(0b00, 2);                           // gender, coding type
  b.bits(0b0000, 4);                         // no range lists: FAP 3 gets +-1080 intra, +-360 predictive; FAP 63 +-720
  b.coder.encode_uniform(2161, 100 + 1080);  // FAP 3 (QP 4): q 100 -> 400
  b.coder.encode_uniform(1441, 700 + 720);   // FAP 63 (QP 1): 700 needs 680 rounded up to 720
  b.coder.flush();
  b.plane(false, 1);
  b.bits(0, 1);  // no skip
  AdaptiveModel jaw, nose;
  jaw.reset(721);
  nose.reset(361);
  b.coder.encode(jaw, -5 + 360);  // q -5 -> 400 - 20
  b.coder.encode(nose, 0 + 180);
  b.coder.flush();
  auto decoded = decode(b.finish());
  ASSERT_TRUE(decoded.ok()) << format_diagnostic(decoded.error());
  const auto& frames = decoded->sequence.frames;
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[0].value(3), 400);
  EXPECT_EQ(frames[0].value(63), 700);
  EXPECT_EQ(frames[1].value(3), 380);
  EXPECT_EQ(frames[1].value(63), 700);
  EXPECT_EQ(decoded->sequence.fps, 30);
  ASSERT_EQ(decoded->warnings.size(), 1u);
  EXPECT_EQ(format_diagnostic(decoded->warnings[0]),
            "t.fba: byte 0: warning: the stream never gives its frame rate; assuming 30 frames per second");
}

TEST(FbaDecoder, TimeCodesSkipsAndFractionalRates) {
  StreamBuilder b;
  b.plane(true, 1);
  b.bits(1, 1);     // is_frame_rate
  b.bits(29, 8);    // 29
  b.bits(15, 4);    // + 15/16
  b.bits(1, 1);     // x 1000/1001: 29.9076 fps
  b.bits(1, 1);     // is_time_code
  b.bits(0, 5);     // 0 h
  b.bits(0, 6);     // 0 min
  b.bits(1, 1);     // marker
  b.bits(2, 6);     // 2 s: frame round(2 x 29.9076) = 60
  b.bits(1, 1);     // skip_frames
  b.bits(15, 4);    // 15 ...
  b.bits(1, 4);     // ... + 1 = 16 skipped
  b.bits(3, 5);     // fap_quant 3
  b.face_masks(2);  // type 10: listed like 01
  b.bits(0b00, 2);
  b.bits(0b1111, 4);
  for (const int v : {1, 0, 1, 1}) b.face_range_list(v);  // FAP 3: I 0..20, P -20..20 (60 / 3)
  b.coder.encode_uniform(21, 10);                         // q 10, step 12 -> 120
  b.coder.flush();
  b.plane(false, 1);
  b.bits(0, 1);
  AdaptiveModel jaw;
  jaw.reset(41);
  b.coder.encode(jaw, -2 + 20);  // -24 -> 96
  b.coder.flush();
  auto decoded = decode(b.finish());
  ASSERT_TRUE(decoded.ok()) << format_diagnostic(decoded.error());
  const auto& frames = decoded->sequence.frames;
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[0].number, 60);
  EXPECT_EQ(frames[1].number, 77);
  EXPECT_EQ(frames[0].value(3), 120);
  EXPECT_EQ(frames[1].value(3), 96);
  EXPECT_NEAR(decoded->info.frame_rate, 29.9375 * 1000.0 / 1001.0, 1e-9);
  EXPECT_EQ(decoded->sequence.fps, 30);
  EXPECT_EQ(decoded->info.skipped_frames, 16);
  EXPECT_EQ(decoded->info.frames, 18);
  ASSERT_EQ(decoded->info.intra_planes.size(), 1u);
  EXPECT_EQ(decoded->info.intra_planes[0].fap_quant, 3);
  EXPECT_EQ(decoded->info.pred_range[2].min, -20);
  ASSERT_EQ(decoded->warnings.size(), 1u);
  EXPECT_NE(decoded->warnings[0].message.find("rounded to 30"), std::string::npos);
}

// Body part of an intra plane: quant index 3 (scale 3), group 1 listing BAPs at positions 0 and
// 2, group 19 with all 6, every range v = 2 (120 / 3 = 40: alphabets of 81 symbols); then the
// segment of 8 intra symbols.
void body_intra(StreamBuilder& b) {
  static const int sizes[] = {3, 4, 4, 6, 6, 5, 5, 7, 7, 12, 15, 18, 18, 12, 16, 16, 13, 13, 6, 22, 22, 22, 22, 22};
  b.bits(3, 5);
  for (int g = 0; g < 24; ++g) {
    b.bits(1, 1);
    if (g == 0) {
      b.bits(1, 2);
      b.bits(0b101, 3);
    } else {
      b.bits(g == 18 ? 3 : 0, 2);
    }
  }
  b.bits(0b00, 2);
  b.bits(0b1111, 4);
  for (int list = 0; list < 4; ++list)
    for (int g = 0; g < 24; ++g)
      for (int j = 0; j < sizes[g]; ++j) {
        if (j % 4 == 0) b.bits(1, 1);
        if ((g == 0 && j != 1) || g == 18) b.bits(2, 5);
      }
  for (int k = 0; k < 8; ++k) b.coder.encode_uniform(81, 7 * k);
  b.coder.flush();
}

// A predictive body segment: 8 adaptive models, which persist from plane to plane.
void body_predictive(StreamBuilder& b, std::vector<AdaptiveModel>& models, int shift) {
  for (std::size_t k = 0; k < 8; ++k) {
    const int s = 40 + static_cast<int>(k) - shift;
    b.coder.encode(models[k], s);
    models[k].update(s);
  }
  b.coder.flush();
}

TEST(FbaDecoder, StepsOverBodyDataInMixedStreams) {
  StreamBuilder b;
  // Plane 1: intra, face and body. Face: FAP 3 with I 0..60 and P -60..60 at fap_quant 1.
  b.plane(true, 3);
  b.bits(0b00, 2);
  b.bits(0, 1);
  b.bits(1, 5);
  b.face_masks(1);
  b.bits(0b00, 2);
  b.bits(0b1111, 4);
  for (const int v : {1, 0, 1, 1}) b.face_range_list(v);
  b.coder.encode_uniform(61, 25);  // 100
  b.coder.flush();
  body_intra(b);
  std::vector<AdaptiveModel> bodies(8);
  for (auto& m : bodies) m.reset(81);
  AdaptiveModel jaw;
  jaw.reset(121);
  // Plane 2: predictive, body only: no face frame, face timing unchanged.
  b.plane(false, 2);
  b.bits(0, 1);
  body_predictive(b, bodies, 1);
  // Plane 3: predictive, face and body.
  b.plane(false, 3);
  b.bits(0, 1);
  b.coder.encode(jaw, 60 + 3);  // +12
  b.coder.flush();
  body_predictive(b, bodies, 2);
  auto decoded = decode(b.finish());
  ASSERT_TRUE(decoded.ok()) << format_diagnostic(decoded.error());
  const auto& frames = decoded->sequence.frames;
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[0].value(3), 100);
  EXPECT_EQ(frames[1].value(3), 112);
  EXPECT_EQ(frames[1].number, 1);
  EXPECT_EQ(decoded->info.body_planes, 3u);
  EXPECT_EQ(decoded->info.planes, 3u);
  ASSERT_GE(decoded->warnings.size(), 1u);
  EXPECT_EQ(format_diagnostic(decoded->warnings[0]),
            "t.fba: byte 4: warning: body animation (BAP) data is parsed and ignored: fapc handles faces only");
}

TEST(FbaDecoder, AcceptsTheLegacyStartCodes) {
  StreamBuilder b(0x00000101);
  b.out.put_start_code_stuffing();
  b.bits(0x00000103, 32);
  b.plane(true, 1);
  b.bits(0b00, 2);
  b.bits(0, 1);
  b.bits(1, 5);
  b.face_masks(1);
  b.bits(0b00, 2);
  b.bits(0b1111, 4);
  for (const int v : {1, 0, 1, 1}) b.face_range_list(v);
  b.coder.encode_uniform(61, 7);
  b.coder.flush();
  auto decoded = decode(b.finish());
  ASSERT_TRUE(decoded.ok()) << format_diagnostic(decoded.error());
  ASSERT_EQ(decoded->sequence.frames.size(), 1u);
  EXPECT_EQ(decoded->sequence.frames[0].value(3), 28);
  EXPECT_EQ(decoded->info.plane_start_codes, 1u);
}

// The test vector of docs/fba-bitstream.md section 11, as bytes (checked there), to break in known
// places.
std::vector<std::uint8_t> test_vector() {
  const std::string hex =
      "000001BAB19001B5E000A00140285059400A140FFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFF51327C8F177DC1F2"
      "13FDEE7F727B4082FC9399F18008808FF600BF000001B1";
  std::vector<std::uint8_t> bytes;
  for (std::size_t i = 0; i < hex.size(); i += 2)
    bytes.push_back(static_cast<std::uint8_t>(std::stoi(hex.substr(i, 2), nullptr, 16)));
  return bytes;
}

void flip_bit(std::vector<std::uint8_t>& bytes, std::size_t bit) {
  bytes[bit / 8] = static_cast<std::uint8_t>(bytes[bit / 8] ^ (0x80 >> (bit % 8)));
}

TEST(FbaDecoder, BrokenStreamsGiveTheByteOffset) {
  ASSERT_EQ(error_of(test_vector()), "decoded");
  // Bit positions from the layout of section 11: the plane starts at bit 32; is_intra, the
  // object mask (2), the temporal header (16) and fap_quant (5) come before the first marker at
  // bit 56; 10 markers and types (30) and 68 listed mask bits later, gender is bit 154 and the
  // coding type bit 155.
  auto bytes = test_vector();
  flip_bit(bytes, 56);
  EXPECT_EQ(error_of(bytes), "t.fba: byte 7: error: marker bit before a FAP mask type is 0 (corrupt stream?)");
  bytes = test_vector();
  flip_bit(bytes, 155);
  EXPECT_EQ(error_of(bytes),
            "t.fba: byte 19: error: FAP coding type 1 (DCT segments) is not supported: no public "
            "description of its code tables exists");
  bytes = test_vector();
  flip_bit(bytes, 34);  // object mask 01 -> 00
  EXPECT_EQ(error_of(bytes),
            "t.fba: byte 4: error: plane with fba_object_mask 00 (neither face nor body data; corrupt stream?)");
  bytes = test_vector();
  flip_bit(bytes, 32);  // is_intra 1 -> 0: a predictive plane first
  EXPECT_EQ(error_of(bytes), "t.fba: byte 4: error: a predictive face plane comes before the first intra plane");
  bytes = test_vector();
  bytes.back() = 0xB5;
  EXPECT_EQ(error_of(bytes), "t.fba: byte 66: error: unexpected start code 0x000001B5 inside the FBA object");
  bytes = test_vector();
  bytes.resize(bytes.size() - 4);
  EXPECT_EQ(error_of(bytes), "t.fba: byte 66: error: stream ends without the end code 0x000001B1 (truncated?)");
  bytes = test_vector();
  bytes[3] = 0xB6;
  EXPECT_EQ(error_of(bytes), "t.fba: byte 0: error: expected the FBA object start code 0x000001BA, found 0x000001B6");
  EXPECT_EQ(error_of({}), "t.fba: byte 0: error: stream ends inside the stream header (truncated?)");

  bytes = test_vector();
  bytes.push_back(0x12);
  bytes.push_back(0x34);
  auto decoded = decode(bytes);
  ASSERT_TRUE(decoded.ok());
  ASSERT_EQ(decoded->warnings.size(), 1u);
  EXPECT_EQ(format_diagnostic(decoded->warnings[0]), "t.fba: byte 70: warning: 2 bytes after the end code are ignored");
}

TEST(FbaDecoder, EveryTruncationIsAnErrorInsideTheData) {
  FapSequence input;
  std::mt19937 rng(1);
  for (int k = 0; k < 30; ++k) {
    FapFrame frame;
    frame.number = k;
    for (const int fap : {1, 3, 19, 48, 52}) frame.mask.set(static_cast<std::size_t>(fap - 1));
    frame.values[2] = static_cast<std::int32_t>(rng() % 800);
    frame.values[18] = static_cast<std::int32_t>(rng() % 300);
    frame.values[47] = static_cast<std::int32_t>(rng() % 9000);
    frame.values[51] = static_cast<std::int32_t>(rng() % 500);
    frame.viseme = {static_cast<int>(rng() % 15), 3, static_cast<int>(rng() % 64), 1};
    input.frames.push_back(frame);
  }
  for (const bool aligned : {false, true}) {
    FbaEncodeOptions options;
    options.align_planes = aligned;
    options.intra_period = 7;
    const auto full = encode_fba(input, options);
    ASSERT_TRUE(full.ok());
    for (std::size_t size = 0; size < full->bytes.size(); ++size) {
      const std::vector<std::uint8_t> part(full->bytes.begin(), full->bytes.begin() + static_cast<long>(size));
      auto decoded = decode(part);
      ASSERT_FALSE(decoded.ok()) << "a stream cut to " << size << " bytes decoded";
      EXPECT_LE(decoded.error().where.byte_offset, static_cast<std::int64_t>(size));
      EXPECT_GE(decoded.error().where.byte_offset, 0);
    }
  }
}

TEST(FbaDecoder, CorruptedStreamsNeverCrash) {
  std::mt19937 rng(77);
  const auto vector = test_vector();
  for (std::size_t bit = 0; bit < vector.size() * 8; ++bit) {
    auto bytes = vector;
    flip_bit(bytes, bit);
    auto decoded = decode(bytes);
    if (!decoded.ok()) {
      EXPECT_GE(decoded.error().where.byte_offset, 0) << bit;
      EXPECT_LE(decoded.error().where.byte_offset, static_cast<std::int64_t>(bytes.size())) << bit;
    }
  }
  for (int trial = 0; trial < 300; ++trial) {
    auto bytes = vector;
    for (int k = 0; k < 4; ++k) bytes[4 + rng() % (bytes.size() - 4)] = static_cast<std::uint8_t>(rng());
    (void)decode(bytes);
    std::vector<std::uint8_t> noise(rng() % 200);
    for (auto& b : noise) b = static_cast<std::uint8_t>(rng());
    noise.insert(noise.begin(), {0x00, 0x00, 0x01, 0xBA});
    (void)decode(noise);
  }
}

}  // namespace
}  // namespace fapc
