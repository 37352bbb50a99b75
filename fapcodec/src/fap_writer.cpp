// The .fap writer: the one form every known reader accepts (docs/fap-files.md section 5).
#include <string>

#include "fapc/codec/fap_file.hpp"

namespace fapc {

namespace {

void append_int(std::string& out, long long v) {
  out += std::to_string(v);
  out += ' ';
}

void end_line(std::string& out, bool trailing_space) {
  if (!trailing_space && !out.empty() && out.back() == ' ') out.pop_back();
  out += '\n';
}

void append_frame(std::string& out, const FapFrame& frame, long long number,
                  const FapWriteOptions& options) {
  for (std::size_t i = 0; i < kFapCount; ++i) append_int(out, frame.mask.test(i) ? 1 : 0);
  end_line(out, options.trailing_space);
  append_int(out, number);
  if (frame.has(1)) {
    const VisemeFields& v = frame.viseme;
    for (int x : {v.select1, v.select2, v.blend, v.def}) append_int(out, x);
  }
  if (frame.has(2)) {
    const ExpressionFields& e = frame.expression;
    for (int x : {e.select1, e.intensity1, e.select2, e.intensity2, e.init_face, e.def})
      append_int(out, x);
  }
  for (int fap = 3; fap <= kFapCount; ++fap)
    if (frame.has(fap)) append_int(out, frame.value(fap));
  end_line(out, options.trailing_space);
}

}  // namespace

std::string safe_header_name(std::string_view name) {
  // The base name only: readers choke on long paths (the reference coder above 127 characters).
  const auto slash = name.find_last_of("/\\");
  if (slash != std::string_view::npos) name.remove_prefix(slash + 1);
  std::string out;
  for (char c : name) {
    const bool blank = c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f';
    out += blank ? '_' : c;
  }
  if (out.size() > 100) out.resize(100);
  return out.empty() ? "fapc" : out;
}

std::string write_fap_text(const FapSequence& sequence, const FapWriteOptions& options) {
  const auto& frames = sequence.frames;
  // With renumbering, absent frames (gaps in the numbers) are filled by repeating the frame
  // before them, so the written frames 0..n-1 keep the sequence's timing.
  long long count = static_cast<long long>(frames.size());
  if (options.renumber && !frames.empty())
    count = frames.back().number - frames.front().number + 1;
  std::string out = "2.1 " + safe_header_name(sequence.name) + " " + std::to_string(sequence.fps) +
                    " " + std::to_string(count) + "\n";
  out.reserve(out.size() + frames.size() * 400);
  for (std::size_t i = 0; i < frames.size(); ++i) {
    if (!options.renumber) {
      append_frame(out, frames[i], frames[i].number, options);
      continue;
    }
    const long long first = frames[i].number - frames.front().number;
    const long long until = i + 1 < frames.size() ? frames[i + 1].number - frames.front().number
                                                  : first + 1;
    for (long long n = first; n < until; ++n) append_frame(out, frames[i], n, options);
  }
  return out;
}

}  // namespace fapc
