// libFuzzer target: the SMIL-Agent reader must never crash or hang, must place every error it
// reports (file:line:col), and whatever it accepts must be a sane timeline: finite clips with
// begin < end and finite values. Speech goes by the letter table (no engine: fast and the same
// everywhere); `speech file=` is refused by an include policy that allows no folder on disk.
#include <cstdint>
#include <string>
#include <string_view>

#include "fapc/smil/smil.hpp"
#include "timeline_checks.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  fapc::ReaderOptions options;
  options.limits.max_runs = 100000;
  options.includes.allowed_folders = {"/nonexistent-fapc-fuzz-folder"};
  return fapc::fuzz::check_timeline_read(fapc::smil::read_smil(text, "fuzz.smil", options));
}
