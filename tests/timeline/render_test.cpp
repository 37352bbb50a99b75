// Curves, blending and rendering against values worked out by hand (docs/timeline.md).
#include <gtest/gtest.h>

#include <cmath>

#include "fapc/transcoder/render.hpp"

namespace fapc {
namespace {

Clip clip(std::string target, double begin, double end, Curve curve, BlendMode blend = BlendMode::add,
          Fill fill = Fill::remove, int line = 1) {
  return Clip{std::move(target), begin, end, 0, std::move(curve), blend, fill, Location::text("t.mimic", line, 3)};
}

TEST(Curve, FadingFunctionsAtExactFractions) {
  // u = 1/2: linear 1/2; sin (1 - cos(pi/2)) / 2 = 1/2; log ln(5.5)/ln(10); exp (sqrt(10)-1)/9.
  EXPECT_DOUBLE_EQ(Curve::ramp(0, 1, 2, Interpolation::linear).value_at(1), 0.5);
  EXPECT_DOUBLE_EQ(Curve::ramp(0, 1, 2, Interpolation::sin).value_at(1), 0.5);
  EXPECT_NEAR(Curve::ramp(0, 1, 2, Interpolation::log).value_at(1), std::log(5.5) / std::log(10), 1e-12);
  EXPECT_NEAR(Curve::ramp(0, 1, 2, Interpolation::exp).value_at(1), (std::sqrt(10.0) - 1) / 9, 1e-12);
  // u = 1/4 of a sin fade from 2 to 6: 2 + 4 * (1 - cos(pi/4)) / 2 = 2 + 2 - sqrt(2).
  EXPECT_NEAR(Curve::ramp(2, 6, 4, Interpolation::sin).value_at(1), 4 - std::sqrt(2.0), 1e-12);
  EXPECT_DOUBLE_EQ(Curve::ramp(2, 6, 4, Interpolation::step).value_at(3.99), 2);
  EXPECT_DOUBLE_EQ(Curve::ramp(2, 6, 4, Interpolation::step).value_at(4), 6);
}

TEST(Curve, KeysHoldOutsideAndJumpAtEqualTimes) {
  const Curve c{{{0, 1}, {1, 3}, {1, 7}, {2, 7}}, std::nullopt};
  EXPECT_DOUBLE_EQ(c.value_at(-1), 1);
  EXPECT_DOUBLE_EQ(c.value_at(0.5), 2);
  EXPECT_DOUBLE_EQ(c.value_at(1), 7);  // the later of two keys at one time
  EXPECT_DOUBLE_EQ(c.value_at(5), 7);
  EXPECT_DOUBLE_EQ(c.left_limit(1), 3);  // the earlier of the two
  EXPECT_DOUBLE_EQ(c.left_limit(0.5), 2);
}

TEST(Curve, PeriodicShapes) {
  Curve sine;
  sine.periodic = Periodic{Periodic::Shape::sine, 1, 3, 4};
  EXPECT_DOUBLE_EQ(sine.value_at(0), 1);
  EXPECT_DOUBLE_EQ(sine.value_at(1), 2);  // quarter period: (1 - cos(pi/2)) / 2 = 1/2
  EXPECT_DOUBLE_EQ(sine.value_at(2), 3);
  Curve triangle;
  triangle.periodic = Periodic{Periodic::Shape::triangle, 0, 10, 4};
  EXPECT_DOUBLE_EQ(triangle.value_at(1), 5);
  EXPECT_DOUBLE_EQ(triangle.value_at(2), 10);
  EXPECT_DOUBLE_EQ(triangle.value_at(3), 5);
  EXPECT_DOUBLE_EQ(triangle.value_at(4), 0);
}

TEST(Curve, APeriodTooShortToDivideByStillGivesAValueInRange) {
  // period=51e-320 in a Mimic script (a fuzzing campaign's input): t / period overflowed, cos(inf)
  // was NaN, and the renderer's conversion of NaN to int was undefined behaviour.
  for (const auto shape : {Periodic::Shape::sine, Periodic::Shape::triangle}) {
    Curve c;
    c.periodic = Periodic{shape, 1, 3, 51e-320};
    for (const double t : {0.0, 0.04, 5.0, 1e6}) {
      const double v = c.value_at(t);
      EXPECT_TRUE(v >= 1 && v <= 3) << t << " -> " << v;
    }
  }
}

TEST(Blend, AddIsTheDefaultAndNeutralIsZero) {
  Timeline t{{clip("jaw", 0, 4, Curve::constant(1)), clip("jaw", 2, 6, Curve::constant(2))}, {}};
  const TimelineEvaluator e(t);
  EXPECT_DOUBLE_EQ(e.value_at("jaw", 1), 1);
  EXPECT_DOUBLE_EQ(e.value_at("jaw", 3), 3);
  EXPECT_DOUBLE_EQ(e.value_at("jaw", 4), 2);        // [begin, end): the first clip is gone at 4
  EXPECT_DOUBLE_EQ(e.value_at("jaw", 4, true), 3);  // but its left limit counts
  EXPECT_DOUBLE_EQ(e.value_at("jaw", 7), 0);
  EXPECT_DOUBLE_EQ(e.value_at("eyelid_left", 1), 0);
}

TEST(Blend, AverageOfAllActiveClips) {
  Timeline t{{clip("jaw", 0, 4, Curve::constant(1)), clip("jaw", 0, 4, Curve::constant(2), BlendMode::average),
              clip("jaw", 0, 4, Curve::constant(6))},
             {}};
  EXPECT_DOUBLE_EQ(TimelineEvaluator(t).value_at("jaw", 1), 3);
}

TEST(Blend, OverwriteThatBeganLastWinsAndTiesGoToTheLaterSource) {
  Timeline t{{clip("jaw", 0, 10, Curve::constant(1), BlendMode::overwrite),
              clip("jaw", 2, 10, Curve::constant(2), BlendMode::overwrite),
              clip("jaw", 2, 10, Curve::constant(3), BlendMode::overwrite),
              clip("jaw", 3, 10, Curve::constant(100), BlendMode::average)},
             {}};
  const TimelineEvaluator e(t);
  EXPECT_DOUBLE_EQ(e.value_at("jaw", 1), 1);
  EXPECT_DOUBLE_EQ(e.value_at("jaw", 5), 3);
}

TEST(Blend, FreezeHoldsUntilTheNextClipOfTheTarget) {
  Timeline t{{clip("jaw", 0, 2, Curve::ramp(0, 4, 2, Interpolation::linear), BlendMode::add, Fill::freeze),
              clip("jaw", 5, 6, Curve::constant(1))},
             {}};
  const TimelineEvaluator e(t);
  EXPECT_DOUBLE_EQ(e.value_at("jaw", 3), 4);
  EXPECT_DOUBLE_EQ(e.value_at("jaw", 5), 1);
  EXPECT_DOUBLE_EQ(e.value_at("jaw", 7), 0);
  EXPECT_EQ(e.span("jaw"), std::make_pair(0.0, 6.0));
}

TEST(Render, FramesRoundHalvesAwayFromZeroAndSpanTheMask) {
  // 1 fps, end 5 s: frames 0..4 at whole seconds (exact in binary). open_jaw ramps 0 -> 10 over
  // [0, 4): 2.5 per frame. raise_b_midlip is -2.5 on [1, 2) and 1 on [3, 4), neutral between.
  Timeline t{{clip("open_jaw", 0, 4, Curve::ramp(0, 10, 4, Interpolation::linear)),
              clip("raise_b_midlip", 1, 2, Curve::constant(-2.5)), clip("raise_b_midlip", 3, 4, Curve::constant(1)),
              clip("head_yaw", 4, 5, Curve::constant(0))},
             {}};
  RenderOptions options;
  options.fps = 1;
  const auto r = render_frames(t, options);
  ASSERT_TRUE(r.ok());
  const auto& frames = r->frames.frames;
  ASSERT_EQ(frames.size(), 5u);
  EXPECT_EQ(frames[1].value(3), 3);  // 2.5 -> 3
  EXPECT_EQ(frames[2].value(3), 5);
  EXPECT_EQ(frames[3].value(3), 8);  // 7.5 -> 8
  EXPECT_FALSE(frames[4].has(3));
  EXPECT_FALSE(frames[0].has(5));
  EXPECT_EQ(frames[1].value(5), -3);  // -2.5 -> -3
  EXPECT_TRUE(frames[2].has(5));      // inside the span, between clips: neutral
  EXPECT_EQ(frames[2].value(5), 0);
  EXPECT_EQ(frames[3].value(5), 1);
  EXPECT_FALSE(frames[4].has(5));
}

TEST(Render, ProfileScalesAndSumsOntoFaps) {
  // jaw -> open_jaw x 1024 in the default profile: 0.5 -> 512, plus 10 directly on open_jaw.
  // lookat_x drives both eyeballs at 523.599 per unit: 10 -> 5235.99 -> 5236.
  Timeline t{{clip("jaw", 0, 1, Curve::constant(0.5)), clip("open_jaw", 0, 1, Curve::constant(10)),
              clip("lookat_x", 0, 1, Curve::constant(10))},
             {}};
  const auto r = render_frames(t, RenderOptions{});
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r->frames.frames[0].value(3), 522);
  EXPECT_EQ(r->frames.frames[0].value(23), 5236);
  EXPECT_EQ(r->frames.frames[0].value(24), 5236);
}

TEST(Render, ClampsWarnOncePerClipAtItsSource) {
  // open_jaw's legal range is +-4320 (1080 rounded up to 1080, times QP 4).
  Timeline t{{clip("open_jaw", 0, 1, Curve::constant(5000), BlendMode::add, Fill::remove, 7)}, {}};
  const auto r = render_frames(t, RenderOptions{});
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r->frames.frames[10].value(3), 4320);
  ASSERT_EQ(r->warnings.size(), 1u);
  EXPECT_EQ(format_diagnostic(r->warnings[0]),
            "t.mimic:7:3: warning: open_jaw of 'open_jaw' reaches 5000 at 0 s, outside "
            "-4320..4320; clamped");
}

TEST(Render, UnknownTargetIsAnErrorAtItsFirstClip) {
  Timeline t{{clip("jw", 0, 1, Curve::constant(1), BlendMode::add, Fill::remove, 4)}, {}};
  const auto r = render_frames(t, RenderOptions{});
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(format_diagnostic(r.error()),
            "t.mimic:4:3: error: unknown animation parameter 'jw'; did you mean jaw, open_jaw, shift_jaw?");
}

TEST(Render, VisemeAndExpressionWeightsFillTheirTwoSlots) {
  Timeline t{
      {clip("viseme.PP", 0, 1, Curve::constant(42)), clip("viseme.FF", 0, 1, Curve::constant(21)),
       clip("expression.joy", 0, 1, Curve::constant(50)), clip("expression.surprise", 0, 1, Curve::constant(10))},
      {}};
  const auto r = render_frames(t, RenderOptions{});
  ASSERT_TRUE(r.ok());
  const FapFrame& f = r->frames.frames[0];
  EXPECT_EQ(f.viseme.select1, 1);  // PP
  EXPECT_EQ(f.viseme.select2, 2);  // FF
  EXPECT_EQ(f.viseme.blend, 42);   // 63 * 42 / 63
  EXPECT_EQ(f.expression, (ExpressionFields{1, 50, 6, 10, 0, 0}));
}

TEST(Curves, ThinnedListKeepsKeysAndJumps) {
  // A linear ramp sampled at 25 fps thins to its two ends; the clip's end is a jump to neutral.
  Timeline t{{clip("jaw", 1, 3, Curve::ramp(0, 2, 2, Interpolation::linear)), clip("jaw", 5, 6, Curve::constant(1))},
             {}};
  const Curves c = render_curves(t, CurveOptions{});
  using P = std::vector<std::pair<double, double>>;
  EXPECT_EQ(c.curves.at("jaw"), (P{{1, 0}, {3, 2}, {3, 0}, {5, 0}, {5, 1}, {6, 1}, {6, 0}}));
  EXPECT_EQ(c.duration, 6);
}

TEST(Curves, VisemeCurveCarriesTheStrongestNumber) {
  // docs/cli.md: FAP 1 appears as "viseme", valued by the strongest viseme's number (PP 1, FF 2).
  Timeline t{{clip("viseme.PP", 0, 1, Curve::constant(63)), clip("viseme.FF", 1, 2, Curve::constant(63))}, {}};
  const Curves c = render_curves(t, CurveOptions{});
  using P = std::vector<std::pair<double, double>>;
  EXPECT_EQ(c.curves.at("viseme"), (P{{0, 1}, {1, 1}, {1, 2}, {2, 2}, {2, 0}}));
  EXPECT_EQ(c.curves.at("viseme.PP"), (P{{0, 63}, {1, 63}, {1, 0}}));
}

TEST(Curves, PerClipCurvesAreLabelledByTheirSource) {
  Timeline t{{clip("jaw", 0, 2, Curve::ramp(0, 1, 2, Interpolation::linear), BlendMode::add, Fill::remove, 5),
              clip("jaw", 0, 2, Curve::constant(1), BlendMode::add, Fill::remove, 5)},
             {}};
  const Curves c = render_clip_curves(t, CurveOptions{});
  using P = std::vector<std::pair<double, double>>;
  EXPECT_EQ(c.curves.at("jaw (t.mimic:5)"), (P{{0, 0}, {2, 1}}));
  EXPECT_EQ(c.curves.at("jaw (t.mimic:5) #2"), (P{{0, 1}, {2, 1}}));
}

TEST(Curves, EveryUseOfOnePlaceHasANumberOfItsOwn) {
  // A macro used four times from line 5, and once from line 6 between its uses.
  Timeline t{{clip("jaw", 0, 1, Curve::constant(1), BlendMode::add, Fill::remove, 5),
              clip("jaw", 1, 2, Curve::constant(2), BlendMode::add, Fill::remove, 5),
              clip("jaw", 2, 3, Curve::constant(3), BlendMode::add, Fill::remove, 6),
              clip("jaw", 3, 4, Curve::constant(4), BlendMode::add, Fill::remove, 5),
              clip("jaw", 4, 5, Curve::constant(5), BlendMode::add, Fill::remove, 5)},
             {}};
  const Curves c = render_clip_curves(t, CurveOptions{});
  ASSERT_EQ(c.curves.size(), 5u);
  EXPECT_EQ(c.curves.at("jaw (t.mimic:5)").front().second, 1);
  EXPECT_EQ(c.curves.at("jaw (t.mimic:5) #2").front().second, 2);
  EXPECT_EQ(c.curves.at("jaw (t.mimic:6)").front().second, 3);
  EXPECT_EQ(c.curves.at("jaw (t.mimic:5) #3").front().second, 4);
  EXPECT_EQ(c.curves.at("jaw (t.mimic:5) #4").front().second, 5);
}

}  // namespace
}  // namespace fapc
