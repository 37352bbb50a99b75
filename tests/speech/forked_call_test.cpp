// The child process each utterance is spoken in (transcoder/speech/src/forked_call.hpp): what it
// returns comes back whole, what it prints comes back as text (never to this process's standard
// error), a crash or an answer past the bound is a value, and nothing it changes reaches the parent.
#include <gtest/gtest.h>

#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "forked_call.hpp"
#include "support/captured_stderr.hpp"

namespace fapc::speech {
namespace {

TEST(ForkedCall, ReturnsTheChildsResultWhole) {
  // Larger than a pipe holds, so the parent must read while the child writes.
  const std::string big(3 << 20, 'x');
  const ForkedOutcome out = call_in_child([&] { return big + "end"; }, big.size() + 3, 100);
  ASSERT_EQ(out.end, ForkedOutcome::End::finished);
  EXPECT_TRUE(out.output == big + "end");
  EXPECT_EQ(out.messages, "");
}

TEST(ForkedCall, WhatTheChildPrintsComesBackBoundedAndNeverReachesStandardError) {
  test::CapturedStderr parent_stderr;
  const ForkedOutcome out = call_in_child(
      [] {
        std::fprintf(stderr, "espeak: No envelope\n");
        for (int i = 0; i < 1000; ++i) std::fprintf(stderr, "0123456789\n");
        return std::string("ok");
      },
      10, 64);
  const std::string printed = parent_stderr.take();
  ASSERT_EQ(out.end, ForkedOutcome::End::finished);
  EXPECT_EQ(out.output, "ok");
  EXPECT_EQ(out.messages.substr(0, 20), "espeak: No envelope\n");
  EXPECT_EQ(out.messages.size(), 64u);
  EXPECT_EQ(out.messages_dropped, 20u + 11000u - 64u);
  EXPECT_EQ(printed, "");
}

TEST(ForkedCall, ACrashIsAValue) {
  const ForkedOutcome out = call_in_child(
      []() -> std::string {
        std::signal(SIGABRT, SIG_DFL);
        std::abort();
      },
      10, 10);
  EXPECT_EQ(out.end, ForkedOutcome::End::failed);
  EXPECT_NE(out.detail, 0);
}

TEST(ForkedCall, AnAnswerPastTheBoundIsRefused) {
  const ForkedOutcome out = call_in_child([] { return std::string(1 << 20, 'y'); }, 1000, 10);
  EXPECT_EQ(out.end, ForkedOutcome::End::too_large);
  EXPECT_TRUE(out.output.size() <= 1000);
}

TEST(ForkedCall, TheChildChangesNothingHere) {
  static int counter = 0;
  const ForkedOutcome out = call_in_child([] { return std::to_string(++counter); }, 10, 10);
  ASSERT_EQ(out.end, ForkedOutcome::End::finished);
  EXPECT_EQ(out.output, "1");
  EXPECT_EQ(counter, 0);
}

}  // namespace
}  // namespace fapc::speech
