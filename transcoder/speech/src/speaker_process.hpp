// The process that speaks for this one (docs/speech.md, "Every utterance alike"). Every utterance
// is spoken in a child forked for it (forked_call.hpp), but a fork taken while other threads run
// copies only the calling thread: a lock another thread held at that instant (the allocator's,
// the dynamic loader's, the sanitizers' own) stays held for ever in the child, which then waits
// for ever. A batch with --jobs did exactly that under AddressSanitizer. So the children are
// forked by a speaker: a process forked once, from this one, while it still has a single thread.
// The speaker has one thread all its life, reads requests from a socket, forks a child for each and
// answers with what the child returned. It ends when this process closes the socket (by ending).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "forked_call.hpp"

namespace fapc::speech {

struct SpeakerWork {
  void (*prepare)();                               // run in the speaker before its first child
  std::string (*serve)(std::string_view request);  // run in a child, once per request
};

enum class SpeakerStart {
  started,        // now, or before: the speaker runs
  other_threads,  // this process already runs other threads: forking now is what must not happen
  failed,         // no socket or no process
};

// Starts the speaker of `work` (one per work, at most kMaxSpeakers) unless it runs already.
// Thread-safe; refuses while this process has more than one thread, unless `even_with_threads`
// (a caller that cannot start earlier accepts the one-time risk).
inline constexpr int kMaxSpeakers = 4;
SpeakerStart start_speaker(const SpeakerWork& work, bool even_with_threads);

// Hands `request` to the speaker of `work` and returns its child's outcome (could_not_start when
// it was not started or has ended; it is not asked again then). Callers serialise their calls.
ForkedOutcome ask_speaker(const SpeakerWork& work, std::string_view request, std::size_t max_output,
                          std::size_t max_messages);

// How many threads this process runs (/proc/self/stat), 0 when that cannot be read.
int thread_count();

}  // namespace fapc::speech
