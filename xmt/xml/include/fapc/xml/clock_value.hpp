// SMIL clock values, the time syntax that both XML front ends (FML and XMT-Omega) read.
#pragma once

#include <optional>
#include <string_view>

namespace fapc::xml {

// "3", "3s", "250ms", "1.5min", "2h", "00:00:03.5", "01:30" (full and partial clock), with
// optional surrounding spaces. Seconds, or nothing when the text is not one.
std::optional<double> parse_clock_value(std::string_view text);

}  // namespace fapc::xml
