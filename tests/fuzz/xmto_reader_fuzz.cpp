// libFuzzer target: the XMT-Omega reader must never crash, must place every error it reports
// (file:line:col), and whatever it accepts must be a sane timeline: finite clips with
// begin < end and finite values. `animation` elements get a small fixed timeline.
#include <cstdint>
#include <string_view>

#include "fapc/xmto/xmto.hpp"
#include "timeline_checks.hpp"

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
  options.load_animation = [](const std::string&, const fapc::Location&) -> fapc::Result<fapc::xmt::IncludedAnimation> {
    return fapc::xmt::IncludedAnimation{included(), {}};
  };
  return fapc::fuzz::check_timeline_read(fapc::xmt::read_xmto(text, "fuzz.xmt", options));
}
