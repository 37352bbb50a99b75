// Mimic compile cost against program size (issue: n log n at worst; a million actions in
// seconds). Prints, per size: atomic actions, source size, compile time (parse, check, schedule,
// lower), time per action, rendering time at 10 fps, and the process's peak memory so far.
// Usage: mimic_compile_bench [max_actions]   (default 1000000)
#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "fapc/transcoder/mimic.hpp"
#include "fapc/transcoder/render.hpp"

namespace {

// One block: 6 atomic actions of every kind, overlapping on shared parameters (jaw twice in a
// parallel, head_rot_x overlapping itself in a sequence), with alignment, connect and blends.
const char* const kBlock =
    "[ jaw <in=0.2,hold=0.3,out=0.2,value=0.1>; eyelid_left ( 0 0.5 1; 0 0.3 0; )\n"
    "  { head_rot_x <in=0.5,value=5>; head_rot_x <left=-0.2,out=0.5,value=3,connect>; }\n"
    "  jaw <min=0,max=0.05,freq=2>; jaw <right,hold=0.5,value=0.05,overwrite>; ]\n";

// Blocks in sequences of ten, those in sequences of a hundred: nesting as well as length.
std::string nested_program(std::size_t actions) {
  const std::size_t blocks = std::max<std::size_t>(1, actions / 6);
  std::string out = "main {\n";
  for (std::size_t i = 0; i < blocks; ++i) {
    if (i % 100 == 0) out += "{\n";
    if (i % 10 == 0) out += "{\n";
    out += kBlock;
    if (i % 10 == 9 || i + 1 == blocks) out += "}\n";
    if (i % 100 == 99 || i + 1 == blocks) out += "}\n";
  }
  return out + "}\n";
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

long peak_megabytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024;
}

}  // namespace

int main(int argc, char** argv) {
  const std::size_t max_actions = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 1000000;
  std::printf("%10s %10s %12s %12s %12s %12s %10s\n", "actions", "source KB", "compile s", "us/action", "clips",
              "render s", "peak MB");
  for (std::size_t n = 1000; n <= max_actions; n *= 10) {
    const std::string source = nested_program(n);
    const auto start = std::chrono::steady_clock::now();
    auto compiled = fapc::compile_mimic(source, "bench.mimic");
    const double compile = seconds_since(start);
    if (!compiled.ok()) {
      std::fprintf(stderr, "%s\n", fapc::format_diagnostic(compiled.error()).c_str());
      return 1;
    }
    const std::size_t actions = n / 6 * 6;
    const auto render_start = std::chrono::steady_clock::now();
    fapc::RenderOptions render;
    render.fps = 10;
    auto frames = fapc::render_frames(compiled->timeline, render);
    const double rendering = seconds_since(render_start);
    std::printf("%10zu %10zu %12.3f %12.3f %12zu %12.3f %10ld\n", actions, source.size() / 1024, compile,
                1e6 * compile / static_cast<double>(actions), compiled->timeline.clips.size(), rendering,
                peak_megabytes());
    std::fflush(stdout);
  }
  return 0;
}
