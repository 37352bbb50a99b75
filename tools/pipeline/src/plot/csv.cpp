// The frames as a table: one row per frame, one column per parameter (docs/cli.md, "Plot"),
// for gnuplot (`set datafile separator ','`) or a spreadsheet.
#include <charconv>

#include "csv.hpp"
#include "fapc/codec/fap_table.hpp"
#include "figure.hpp"

namespace fapc::pipeline::plot {

namespace {

template <class T>
void append_number(std::string& out, T value) {
  char text[32];
  out.append(text, std::to_chars(text, text + sizeof text, value).ptr);
}

}  // namespace

Result<std::string> frames_csv(const FapSequence& sequence, const std::string& selection, const std::string& input) {
  std::vector<bool> used(kFapCount + 1, false);
  for (const FapFrame& frame : sequence.frames)
    for (int fap = 1; fap <= kFapCount; ++fap)
      used[static_cast<std::size_t>(fap)] = used[static_cast<std::size_t>(fap)] || frame.has(fap);
  std::vector<std::string> available;
  for (int fap = 1; fap <= kFapCount; ++fap)
    if (used[static_cast<std::size_t>(fap)]) available.emplace_back(find_fap(fap)->name);
  std::vector<int> columns;
  if (!available.empty()) {
    auto chosen = select_targets(selection, available, input);
    if (!chosen) return chosen.error();
    for (const std::string& name : *chosen) columns.push_back(find_fap(name)->number);
  }
  std::string out = "frame,time_s";
  for (const int fap : columns) out += ',', out += find_fap(fap)->name;
  out += '\n';
  for (const FapFrame& frame : sequence.frames) {
    append_number(out, frame.number);
    out += ',';
    append_number(out, static_cast<double>(frame.number) / sequence.fps);
    for (const int fap : columns) {
      out += ',';
      if (!frame.has(fap)) continue;  // not sent in this frame: an empty cell
      append_number(out, fap == 1   ? static_cast<long long>(frame.viseme.select1)
                         : fap == 2 ? static_cast<long long>(frame.expression.select1)
                                    : static_cast<long long>(frame.value(fap)));
    }
    out += '\n';
  }
  return out;
}

}  // namespace fapc::pipeline::plot
