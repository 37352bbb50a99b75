// libFuzzer target: the combine expression language must never crash. Operands are stand-ins
// (a short animation, or a state for names ending in .xpr): no file is read.
#include <cstdint>
#include <string>
#include <string_view>

#include "fapc/transcoder/algebra_expression.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const auto load = [](const std::string& name, int) -> fapc::Result<fapc::algebra::Value> {
    fapc::algebra::Value value;
    fapc::algebra::FacialState state;
    state.at(3) = static_cast<std::int32_t>(name.size() * 10);
    state.at(31) = -40;
    if (name.ends_with(".xpr")) {
      value.state = state;
    } else {
      value.animation.fps = name.size() % 2 ? 25 : 30;
      value.animation.frames.assign(5, state);
    }
    return value;
  };
  // A frame limit of 2^14 instead of 2^20: the limits themselves are tested by algebra_tests;
  // here an input at the default work budget (4 x 2^20 frames) would take seconds under the
  // sanitizers and trip libFuzzer's timeout without being a finding.
  (void)fapc::algebra::evaluate(text, load, std::int64_t{1} << 14);
  return 0;
}
