// `fapc plot -o X.csv`: the frames as a table (columns in docs/cli.md, "Plot").
#pragma once

#include <string>

#include "fapc/codec/diagnostic.hpp"
#include "fapc/codec/fap_sequence.hpp"

namespace fapc::pipeline::plot {

// "frame,time_s,<FAP name>..." then one row per frame; `selection` as PlotOptions::faps.
Result<std::string> frames_csv(const FapSequence& sequence, const std::string& selection, const std::string& input);

}  // namespace fapc::pipeline::plot
