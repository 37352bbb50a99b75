// libFuzzer target: the XMT-Omega reader must never crash, must place every error it reports
// (file:line:col), and whatever it accepts must be a sane timeline: finite clips with
// begin < end and finite values. `animation` elements get a small fixed timeline.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "fapc/transcoder/render.hpp"
#include "fapc/xmt/xmto.hpp"

namespace {

fapc::Timeline included() {
  fapc::Timeline t;
  fapc::Clip clip;
  clip.target = "open_jaw";
  clip.end = 0.5;
  clip.curve = fapc::Curve::ramp(0, 100, 0.5, fapc::Interpolation::linear);
  t.clips.push_back(clip);
  return t;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  fapc::xmt::XmtoOptions options;
  options.load_animation = [](const std::string&, const fapc::Location&)
      -> fapc::Result<fapc::xmt::IncludedAnimation> { return fapc::xmt::IncludedAnimation{included(), {}}; };
  const auto read = fapc::xmt::read_xmto(text, "fuzz.xmt", options);
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
