// One piece of work run in a child process forked from this one, its result handed back through
// a pipe (docs/speech.md, "Every utterance alike"). eSpeak NG keeps synthesis state in globals
// that no call of its API resets (the wave generator's phase, pitch flutter and gain, the last
// pitch and amplitude commands...), so an utterance sounded different after another one. A child
// forked from a process that has never spoken starts from the same state each time, and takes
// whatever the utterance changed with it when it ends. The child also keeps the engine's own
// messages (written to its standard error and output) off the terminal: they come back as text,
// and a crash of the engine is a value, not the end of fapc.
#pragma once

#include <cstddef>
#include <functional>
#include <string>

namespace fapc::speech {

struct ForkedOutcome {
  enum class End {
    finished,         // `output` holds what the work returned
    failed,           // the child died (detail: the signal) or exited otherwise (detail: -status)
    could_not_start,  // no pipe or no process (detail: errno)
    too_large,        // the child wrote more than the caller allows
  };
  End end = End::could_not_start;
  int detail = 0;
  std::string output;
  // What the child wrote to its standard error (and unbuffered to its standard output): at most
  // the caller's bound, the rest counted in `messages_dropped`.
  std::string messages;
  std::size_t messages_dropped = 0;
};

// Runs `work` in a child of this process and returns what it returned. The child writes only to
// the two pipes and ends with _exit (no atexit handler, no flush of the parent's buffered
// output). Call it only from a process with a single thread, as the speaker is
// (speaker_process.hpp): the child has only the calling thread, and a lock another thread held
// at the fork would never be released there.
ForkedOutcome call_in_child(const std::function<std::string()>& work, std::size_t max_output, std::size_t max_messages);

}  // namespace fapc::speech
