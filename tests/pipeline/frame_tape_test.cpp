// The tape between the streamed compile's two passes gives back every frame it was given, field
// for field, and drops itself (rather than grow) past its budget.
#include <gtest/gtest.h>

#include <random>

#include "frame_tape.hpp"

namespace fapc::pipeline {
namespace {

bool identical(const FapFrame& a, const FapFrame& b) {
  return a.number == b.number && a.mask == b.mask && a.values == b.values && a.viseme == b.viseme &&
         a.expression == b.expression;
}

// Frames of every kind the tape codes differently: masks that change, gaps and backward numbers,
// large and negative values, FAP 1/2 fields, and slots outside the mask that are not at rest.
std::vector<FapFrame> varied_frames() {
  std::mt19937 random(7);
  std::vector<FapFrame> frames;
  for (int k = 0; k < 2000; ++k) {
    FapFrame f;
    f.number = k % 97 == 5 ? k + 40 : (k % 211 == 3 ? k - 1000 : k);
    for (int fap = 1; fap <= kFapCount; ++fap)
      if (random() % (k % 50 < 25 ? 3 : 11) == 0)
        f.set(fap, static_cast<std::int32_t>(random() % 4001) - 2000 + (k % 300 == 0 ? 2000000000 : 0));
    if (f.has(1)) f.viseme = {static_cast<int>(random() % 15), static_cast<int>(random() % 15), 63, 1};
    if (f.has(2)) f.expression = {1, 2, 3, 4, 1, 0};
    if (k % 13 == 0) f.values[static_cast<std::size_t>(random() % kFapCount)] = -5;  // maybe unmasked
    if (k % 17 == 0) f.viseme.blend = 9;
    if (k % 19 == 0) f.expression.def = 1;
    frames.push_back(f);
  }
  return frames;
}

TEST(FrameTape, GivesBackEveryFrameFieldForField) {
  const std::vector<FapFrame> frames = varied_frames();
  FrameTape tape(std::size_t{1} << 30);
  for (const FapFrame& f : frames) ASSERT_TRUE(tape.record(f));
  EXPECT_FALSE(tape.dropped());
  FrameTape::Player player = tape.play();
  for (std::size_t k = 0; k < frames.size(); ++k) ASSERT_TRUE(identical(player.next(), frames[k])) << "frame " << k;
}

TEST(FrameTape, KeepsValuesOutsideAMaskFromTheFirstFrameOn) {
  // The first frame's mask is the tape's starting one (none): its slots must still count as outside.
  std::vector<FapFrame> frames(3);
  frames[0].values[5] = 7;  // no FAP masked
  frames[1].set(3, 10);
  frames[1].values[20] = -4;
  frames[2].number = 2;
  FrameTape tape(std::size_t{1} << 20);
  for (std::size_t k = 0; k < frames.size(); ++k) {
    frames[k].number = static_cast<std::int64_t>(k);
    ASSERT_TRUE(tape.record(frames[k]));
  }
  FrameTape::Player player = tape.play();
  for (std::size_t k = 0; k < frames.size(); ++k) ASSERT_TRUE(identical(player.next(), frames[k])) << "frame " << k;
}

TEST(FrameTape, GivesBackFramesAcrossItsBlocks) {
  // Enough frames for several of the tape's 1 MiB blocks, each block freed as the player leaves it.
  std::vector<FapFrame> frames;
  for (int round = 0; round < 32; ++round)
    for (const FapFrame& f : varied_frames()) frames.push_back(f);
  FrameTape tape(std::size_t{1} << 30);
  for (const FapFrame& f : frames) ASSERT_TRUE(tape.record(f));
  ASSERT_GT(tape.bytes(), std::size_t{3} << 20);
  FrameTape::Player player = tape.play();
  for (std::size_t k = 0; k < frames.size(); ++k) ASSERT_TRUE(identical(player.next(), frames[k])) << "frame " << k;
}

TEST(FrameTape, CostsAByteOrTwoPerMaskedFapOfASmoothAnimation) {
  FrameTape tape(std::size_t{1} << 30);
  for (int k = 0; k < 1000; ++k) {
    FapFrame f;
    f.number = k;
    for (int fap = 3; fap <= 7; ++fap) f.set(fap, (k * fap) % 200);
    tape.record(f);
  }
  // 1 flag byte and 5 differences of at most 2 bytes, plus the first frame's mask and number.
  EXPECT_LE(tape.bytes(), 1000u * 11 + 16);
}

TEST(FrameTape, DropsItselfPastItsBudget) {
  FrameTape tape(1000);
  int recorded = 0;
  for (const FapFrame& f : varied_frames())
    if (tape.record(f)) ++recorded;
  EXPECT_TRUE(tape.dropped());
  EXPECT_GT(recorded, 0);
  EXPECT_EQ(tape.bytes(), 0u);
}

}  // namespace
}  // namespace fapc::pipeline
