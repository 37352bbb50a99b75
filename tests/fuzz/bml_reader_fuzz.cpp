// libFuzzer target: the BML reader (constraint solving, sync references, lowering through the
// vocabulary) must never crash or hang, must place every error it reports (file:line:col), and
// whatever it accepts must be a sane timeline. Speech is timed by the letter table (no engine):
// the engine has a target of its own (speech).
#include <cstdint>
#include <string_view>

#include "fapc/bml/bml.hpp"
#include "timeline_checks.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  fapc::ReaderOptions options;
  options.limits.max_runs = 4096;  // the limit is tested by bml_tests; here it keeps inputs quick
  options.speech.max_seconds = 60;
  // Recorded speech names files (resolved from the working folder): keep any it finds small.
  options.limits.max_decompressed_bytes = 1 << 20;
  return fapc::fuzz::check_timeline_read(fapc::bml::read_bml(text, "fuzz.xml", options));
}
