// GrowingTimeline against a second implementation: a TimelineEvaluator built, after every add,
// over the clips added so far (what the XMT-Omega reader did per to-animation before). Random
// clips on few targets, on a coarse time grid so begins, ends and queries often coincide, with
// every blend mode and both fills, added in random order.
#include <gtest/gtest.h>

#include <random>

#include "fapc/transcoder/growing_timeline.hpp"
#include "fapc/transcoder/render.hpp"

namespace fapc {
namespace {

Clip random_clip(std::mt19937& rng) {
  std::uniform_int_distribution<int> grid(0, 20);
  std::uniform_int_distribution<int> length(1, 6);
  std::uniform_int_distribution<int> pick(0, 2);
  Clip clip;
  clip.target = pick(rng) == 0 ? "open_jaw" : "head_yaw";
  clip.begin = grid(rng) * 0.5;
  clip.end = clip.begin + length(rng) * 0.5;
  clip.curve = Curve::ramp(grid(rng), grid(rng) * 10, clip.end - clip.begin, Interpolation::linear);
  clip.blend = static_cast<BlendMode>(pick(rng));
  clip.fill = pick(rng) == 0 ? Fill::freeze : Fill::remove;
  return clip;
}

TEST(GrowingTimeline, AgreesWithAnEvaluatorRebuiltAfterEveryAdd) {
  for (unsigned seed = 1; seed <= 200; ++seed) {
    std::mt19937 rng(seed);
    std::vector<Clip> planned;
    const int count = 1 + static_cast<int>(rng() % 30);
    for (int i = 0; i < count; ++i) planned.push_back(random_clip(rng));
    std::vector<std::size_t> order(planned.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::shuffle(order.begin(), order.end(), rng);

    std::vector<PlannedClip> plan;
    for (const Clip& clip : planned) plan.push_back({clip.target, clip.begin});
    Timeline so_far;  // the clips added, in add order: the growing timeline reads them there
    GrowingTimeline growing(plan, so_far.clips);
    for (const std::size_t i : order) {
      so_far.clips.push_back(planned[i]);
      growing.add(i, so_far.clips.size() - 1);
      const TimelineEvaluator reference(so_far);
      for (int q = 0; q <= 30; ++q) {
        const double t = q * 0.5;
        for (const char* target : {"open_jaw", "head_yaw"}) {
          ASSERT_EQ(growing.value_at(target, t), reference.value_at(target, t))
              << "seed " << seed << " target " << target << " t " << t;
        }
      }
    }
  }
}

TEST(GrowingTimeline, AnUnplannedTargetIsNeutral) {
  const std::vector<Clip> none;
  GrowingTimeline growing({}, none);
  EXPECT_EQ(growing.value_at("open_jaw", 1), 0);
}

}  // namespace
}  // namespace fapc
