// libFuzzer target: the FML-APML and APML readers (docs/intentions.md) must never crash or hang,
// must place every error they report (file:line:col), and what they accept must be a sane
// timeline. Each input is read by both (the one whose root it is not refuses it at once). Speech
// goes by the letter table (no engine: fast and the same everywhere); the frame budget is the
// command line's at 25 fps, as `fapc compile` reads these documents.
#include <cstdint>
#include <string>
#include <string_view>

#include "fapc/intent/intent.hpp"
#include "timeline_checks.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  fapc::intent::IntentOptions options;
  options.frames.fps = 25;
  options.limits.max_runs = 2000;
  fapc::fuzz::check_timeline_read(fapc::intent::read_fml_apml(text, "fuzz.xml", options));
  return fapc::fuzz::check_timeline_read(fapc::intent::read_apml(text, "fuzz.xml", options));
}
