// The speaker process (transcoder/speech/src/speaker_process.hpp): forked once while this process
// has a single thread, it answers every request from a fresh child of its own, so what one request
// changes never reaches the next, and a crash is an answer, not the speaker's end.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <future>
#include <string>
#include <thread>

#include "speaker_process.hpp"

namespace fapc::speech {
namespace {

int counter = 0;
int prepared = 0;

void count_preparation() { ++prepared; }

// "crash" kills the child; anything else comes back with the prepared count and a counter that a
// speaker which answered in its own process would raise at every request.
std::string answer(std::string_view request) {
  if (request == "crash") {
    std::signal(SIGSEGV, SIG_DFL);
    std::raise(SIGSEGV);
  }
  return std::string(request) + " " + std::to_string(prepared) + " " + std::to_string(++counter);
}

constexpr SpeakerWork kWork{count_preparation, answer};

TEST(SpeakerProcess, EveryRequestStartsFromTheSpeakersStateAndACrashIsAnAnswer) {
  // With other threads allowed: a test before this one in the process may have started the speech
  // engine, whose initialisation starts an (idle) thread of its own.
  ASSERT_EQ(start_speaker(kWork, true), SpeakerStart::started);
  EXPECT_EQ(start_speaker(kWork, true), SpeakerStart::started);  // once only
  for (const char* text : {"one", "two"}) {
    const ForkedOutcome out = ask_speaker(kWork, text, 100, 100);
    ASSERT_EQ(out.end, ForkedOutcome::End::finished);
    EXPECT_EQ(out.output, std::string(text) + " 1 1");  // prepared once, in the speaker; counted in the child
  }
  const ForkedOutcome crashed = ask_speaker(kWork, "crash", 100, 100);
  EXPECT_EQ(crashed.end, ForkedOutcome::End::failed);
  EXPECT_EQ(crashed.detail, SIGSEGV);
  EXPECT_EQ(ask_speaker(kWork, "three", 100, 100).output, "three 1 1");
  EXPECT_EQ(prepared, 0);  // none of it ran here
  EXPECT_EQ(counter, 0);
  // An answer past the bound is refused, and the speaker goes on.
  EXPECT_EQ(ask_speaker(kWork, std::string(1000, 'x'), 10, 10).end, ForkedOutcome::End::too_large);
  EXPECT_EQ(ask_speaker(kWork, "four", 100, 100).output, "four 1 1");
}

std::string echo(std::string_view request) { return std::string(request); }

TEST(SpeakerProcess, IsNotForkedWhileOtherThreadsRun) {
  const int before = thread_count();
  ASSERT_GE(before, 1);
  std::promise<void> release;
  std::thread other([future = release.get_future()]() mutable { future.wait(); });
  EXPECT_EQ(thread_count(), before + 1);
  const SpeakerWork work{nullptr, echo};
  EXPECT_EQ(start_speaker(work, false), SpeakerStart::other_threads);
  EXPECT_EQ(ask_speaker(work, "x", 10, 10).end, ForkedOutcome::End::could_not_start);
  // A caller that cannot start earlier may take the risk.
  EXPECT_EQ(start_speaker(work, true), SpeakerStart::started);
  release.set_value();
  other.join();
  EXPECT_EQ(thread_count(), before);
  EXPECT_EQ(ask_speaker(work, "x", 10, 10).output, "x");
}

TEST(SpeakerProcess, EndsWhenThisProcessEnds) {
  // A child of this test starts a speaker, which inherits the write end of this pipe (the speaker
  // keeps the descriptors it was forked with, but for the standard ones), and ends. Reading
  // this end gives end-of-file only once the speaker has ended too.
  int ends[2];
  ASSERT_EQ(::pipe(ends), 0);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    ::close(ends[0]);
    const SpeakerWork work{nullptr, echo};
    const bool answered =
        start_speaker(work, false) == SpeakerStart::started && ask_speaker(work, "y", 10, 10).output == "y";
    ::_exit(answered ? 0 : 1);
  }
  ::close(ends[1]);
  char byte;
  EXPECT_EQ(::read(ends[0], &byte, 1), 0);
  ::close(ends[0]);
  int status = 0;
  ::waitpid(child, &status, 0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
}

}  // namespace
}  // namespace fapc::speech
