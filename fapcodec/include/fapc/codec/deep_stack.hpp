// Work whose recursion is bounded but deep (an included input read inside another one's reader,
// Xerces-C's validation): run on a thread of its own with a stack of known size, so that the
// bound, not the caller's remaining stack, decides whether it fits (docs/security.md, "Depth
// limits"). std::thread cannot choose its stack size; this uses pthread attributes.
#pragma once

#include <cstddef>
#include <functional>

namespace fapc {

// 256 MB of address space; only the pages a run touches are ever backed by memory.
inline constexpr std::size_t kDeepStackBytes = std::size_t{256} << 20;

// Runs `work` on a new thread with a stack of `stack_bytes` and waits for it to finish. An
// exception leaving `work` is thrown again here. When no thread can be created, `work` runs on
// the caller's thread.
void run_on_deep_stack(const std::function<void()>& work, std::size_t stack_bytes = kDeepStackBytes);

}  // namespace fapc
