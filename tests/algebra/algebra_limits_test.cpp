// The Algebra's expressions against the frame limit and hostile delays (docs/security.md and
// docs/algebra.md): refused at the operator's column before the frames are allocated.
#include <gtest/gtest.h>

#include "fapc/codec/codes.hpp"
#include "fapc/transcoder/algebra_expression.hpp"

namespace fapc::algebra {
namespace {

// Every operand is a 2 s animation at `fps` (a slot per frame, all holding a state).
OperandLoader animations(int fps) {
  return [fps](const std::string&, int) -> Result<Value> {
    Value v;
    v.animation.fps = fps;
    v.animation.frames.assign(static_cast<std::size_t>(2 * fps), FacialState{});
    return v;
  };
}

TEST(AlgebraLimits, ANegativeDelayIsAnErrorNotASilentCut) {
  // joy.fap >> -5 used to drop every frame of a short animation without a word.
  const auto r = evaluate("joy.fap >> -5", animations(25));
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(format_diagnostic(r.error()), "<expression>:1:9: error: a delay is from 0 to 86400 s (a day); -5 is not");
}

TEST(AlgebraLimits, ALongDelayAtAHighRateIsRefusedBeforeAllocating) {
  // A day at 1000 fps: 86,402,000 slots (some 23 GB) before the limit.
  const auto r = evaluate("joy.fap >> 86400", animations(1000));
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().kind, ErrorKind::limit_exceeded);
  EXPECT_EQ(format_diagnostic(r.error()),
            "<expression>:1:9: error: the delayed animation spans 86402000 frames at 1000 fps: more than the "
            "limit of 1048576 frames (--max-frames N raises it)");
  EXPECT_TRUE(evaluate("joy.fap >> 60", animations(1000)).ok());
}

TEST(AlgebraLimits, ChainedDelaysAddUpAgainstTheLimitAndActAsOne) {
  // 50 + 50 slots on a 50-slot animation: 150, past a limit of 120, though each '>>' alone is not.
  const auto r = evaluate("joy.fap >> 2 >> 2", animations(25), 120);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().kind, ErrorKind::limit_exceeded);
  EXPECT_EQ(r.error().where.column, 14);
  // Applied once: the same slots as one delay of the sum (2,000 chained '>> 0.04' once copied
  // the animation 2,000 times).
  std::string chain = "joy.fap";
  for (int i = 0; i < 2000; ++i) chain += " >> 0.04";
  const auto chained = evaluate(chain, animations(25));
  const auto single = evaluate("joy.fap >> 80", animations(25));
  ASSERT_TRUE(chained.ok() && single.ok());
  EXPECT_EQ(chained->animation.frames.size(), 2050u);
  EXPECT_EQ(chained->animation.frames, single->animation.frames);
}

TEST(AlgebraLimits, ALongChainOfOperatorsIsBoundedInAllNotOnlyEachOne) {
  // A fuzzing campaign's input: '+' after '+' of delayed copies, each operator within the frame
  // limit, together making far more frames than any output (15 KB took 0.8 s; 1 MB, hours).
  // With a limit of 1000, 8000 frames in all: the chain is refused where it passes them.
  std::string chain = "a.fap";
  for (int i = 0; i < 200; ++i) chain += " + a.fap >> 0.04";
  const auto r = evaluate(chain, animations(25), 1000);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().kind, ErrorKind::limit_exceeded);
  EXPECT_GT(r.error().where.column, 1);
  EXPECT_LT(r.error().where.column, static_cast<int>(chain.size()));
  std::string short_chain = "a.fap";
  for (int i = 0; i < 10; ++i) short_chain += " + a.fap >> 0.04";
  EXPECT_TRUE(evaluate(short_chain, animations(25), 1000).ok());
}

TEST(AlgebraLimits, AnAmplifierThatWouldSaturateAFapValueIsRefusedAtTheAmplifier) {
  const OperandLoader jaw = [](const std::string&, int) -> Result<Value> {
    Value v;
    v.animation.fps = 25;
    FacialState s;
    s.at(3) = 500;
    v.animation.frames.assign(2, s);
    return v;
  };
  for (const char* text : {"1e308 * joy.fap", "joy.fap * -1e308", "1e7 * joy.fap"}) {
    const auto r = evaluate(text, jaw);
    ASSERT_FALSE(r.ok()) << text;
    EXPECT_EQ(r.error().where.column, text[0] == 'j' ? 11 : 1) << text;
  }
  EXPECT_TRUE(evaluate("1e6 * joy.fap", jaw).ok());  // 5e8 still fits in 32 bits
}

TEST(AlgebraLimits, MeetingOnTheHigherRateCountsAgainstTheLimit) {
  // 2 s at 25 fps brought to 1000 fps is 2000 slots; the limit is 1000.
  const OperandLoader mixed = [](const std::string& name, int) -> Result<Value> {
    const int fps = name == "fast.fap" ? 1000 : 25;
    Value v;
    v.animation.fps = fps;
    v.animation.frames.assign(static_cast<std::size_t>(name == "fast.fap" ? 10 : 2 * fps), FacialState{});
    return v;
  };
  const auto r = evaluate("slow.fap + fast.fap", mixed, 1000);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().kind, ErrorKind::limit_exceeded);
  EXPECT_EQ(r.error().where.column, 10);
  EXPECT_TRUE(evaluate("slow.fap + fast.fap", mixed, 2000).ok());
}

TEST(AlgebraLimits, AnOperandThatCannotBeReadIsReportedWhereTheExpressionNamesIt) {
  const OperandLoader missing = [](const std::string& name, int) -> Result<Value> {
    return make_error(codes::io::cannot_open, Location::whole_file("folder/" + name),
                      "cannot open file: No such file or directory");
  };
  const auto r = evaluate("0.5 * nothere.fap", missing);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().kind, ErrorKind::io);
  EXPECT_EQ(format_diagnostic(r.error()),
            "<expression>:1:7: error: operand 'folder/nothere.fap': cannot open file: No such file or directory");
}

}  // namespace
}  // namespace fapc::algebra

namespace fapc::algebra {
namespace {

// 1e300 * X + 1e300 * X: both halves saturate at 2^31 - 1 and their int32 sum overflowed
// (undefined behaviour, caught by UBSan); the sum saturates too.
TEST(AlgebraLimits, SaturatedHalvesOfASumDoNotOverflow) {
  FacialState big;
  big.at(3) = 1000;
  big.at(4) = -1000;
  const FacialState s = sum(amplify(big, 1e300), amplify(big, 1e300), 0.5);
  EXPECT_EQ(s.at(3), 2147483647);
  EXPECT_EQ(s.at(4), -2147483647 - 1);
}

}  // namespace
}  // namespace fapc::algebra
