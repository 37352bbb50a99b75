// The progress bar's line and the warning counts' numbers (tools/fapc/progress.hpp, report.hpp).
// Expected lines worked out by hand: 12 of 100 done in 4 s is 3.0/s, 88 left take 29.3 s.
#include <gtest/gtest.h>

#include "fapc/progress.hpp"
#include "fapc/report.hpp"

namespace fapc::cli {
namespace {

TEST(Progress, LineShowsDoneTotalRateAndTimeLeft) {
  EXPECT_EQ(progress_line("inputs", 12, 100, 4.0, 10), "[#.........] 12/100 inputs  3.0/s  0:29 left");
  EXPECT_EQ(progress_line("", 50, 100, 2.0, 4), "[##..] 50/100  25/s  0:02 left");
}

TEST(Progress, NoRateBeforeAnythingIsDoneAndNoTimeLeftAtTheEnd) {
  EXPECT_EQ(progress_line("frames", 0, 10, 0.0, 5), "[.....] 0/10 frames");
  EXPECT_EQ(progress_line("frames", 10, 10, 5.0, 5), "[#####] 10/10 frames  2.0/s");
}

TEST(Progress, NothingToDoIsAnEmptyBar) { EXPECT_EQ(progress_line("", 0, 0, 1.0, 3), "[...] 0/0"); }

TEST(Progress, ClockText) {
  EXPECT_EQ(clock_text(0), "0:00");
  EXPECT_EQ(clock_text(59.6), "1:00");
  EXPECT_EQ(clock_text(3723), "1:02:03");
}

TEST(Progress, NotATerminalMeansNoBar) {
  // ctest runs tests with standard error on a pipe or a file, never a terminal.
  EXPECT_FALSE(progress_wanted());
  ProgressBar bar(progress_wanted());
  EXPECT_FALSE(bar.enabled());
}

TEST(WarningCounts, ThousandsSeparators) {
  EXPECT_EQ(with_thousands(0), "0");
  EXPECT_EQ(with_thousands(999), "999");
  EXPECT_EQ(with_thousands(6509), "6,509");
  EXPECT_EQ(with_thousands(1234567), "1,234,567");
  EXPECT_EQ(with_thousands(-1000), "-1,000");
}

}  // namespace
}  // namespace fapc::cli
