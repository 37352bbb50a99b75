// libFuzzer target: the Mimic compiler (lexer, parser, checks, scheduler, lowering) must never
// crash, and whatever it accepts must render. Expression files are not read: a fuzzer must not
// touch the disk.
#include <cstdint>
#include <string_view>

#include "fapc/transcoder/mimic.hpp"
#include "fapc/transcoder/render.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view source(reinterpret_cast<const char*>(data), size);
  fapc::ReaderOptions options;
  options.read_file = [](const std::string&) -> fapc::Result<std::string> {
    return std::string("raise_l_cornerlip 100\nopen_jaw 50\n");
  };
  auto program = fapc::compile_mimic(source, "fuzz.mimic", options);
  if (!program.ok()) return 0;
  // Long animations are legal but slow to render; the renderer is not what is fuzzed here.
  if (program->timeline.end() > 600) return 0;
  fapc::RenderOptions render;
  render.fps = 10;
  (void)fapc::render_frames(program->timeline, render);
  (void)fapc::render_curves(program->timeline, fapc::CurveOptions{10, 1e-6});
  return 0;
}
