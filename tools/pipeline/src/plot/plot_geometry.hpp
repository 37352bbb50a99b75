// The horizontal geometry every panel shares, in pixels: the time axis that draw.cpp draws on and
// that column_picks.cpp thins lines to.
#pragma once

namespace fapc::pipeline::plot {

constexpr double kWidth = 960;
constexpr double kLeft = 90;  // room for the y tick labels and the y-axis title
constexpr double kRight = 20;
constexpr double kInset = 6;  // points at the ends of the time axis stay clear of the frame

}  // namespace fapc::pipeline::plot
