// libFuzzer target: the FML reader must never crash or hang, must place every error it reports
// (file:line:col), and whatever it accepts must be a sane timeline: finite clips with
// begin < end and finite values. `talk file=` gets a small fixed .pho text; a 10 s duration ends
// indefinite repeats as --duration does.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "fapc/transcoder/render.hpp"
#include "fapc/xmt/fml.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  fapc::xmt::FmlOptions options;
  options.duration = 10;
  options.read_file = [](const std::string&) -> fapc::Result<std::string> {
    return std::string("_ 50\nh 60\n@ 80 50 120\nl 60\n@U 150\n_ 40\n");
  };
  const auto read = fapc::xmt::read_fml(text, "fuzz.fml", options);
  if (!read.ok()) {
    if (read.error().where.line <= 0) std::abort();  // every error in the document has a place
    return 0;
  }
  const fapc::Timeline& timeline = read->timeline;
  if (!std::isfinite(timeline.end()) || timeline.end() < 0) std::abort();
  const fapc::TimelineEvaluator evaluator(timeline);
  std::size_t checked = 0;
  for (const fapc::Clip& clip : timeline.clips) {
    if (!(clip.begin < clip.end) || !std::isfinite(clip.begin) || !std::isfinite(clip.end)) std::abort();
    if (checked++ < 64 && !std::isfinite(evaluator.value_at(clip.target, clip.begin))) std::abort();
  }
  return 0;
}
