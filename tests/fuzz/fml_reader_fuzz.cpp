// libFuzzer target: the FML reader must never crash or hang, must place every error it reports
// (file:line:col), and whatever it accepts must be a sane timeline: finite clips with
// begin < end and finite values. `talk file=` gets a small fixed .pho text; a 10 s duration ends
// indefinite repeats as --duration does.
#include <cstdint>
#include <string>
#include <string_view>

#include "fapc/fml/fml.hpp"
#include "timeline_checks.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  fapc::ReaderOptions options;
  options.duration = 10;
  options.read_file = [](const std::string&) -> fapc::Result<std::string> {
    return std::string("_ 50\nh 60\n@ 80 50 120\nl 60\n@U 150\n_ 40\n");
  };
  return fapc::fuzz::check_timeline_read(fapc::fml::read_fml(text, "fuzz.fml", options));
}
