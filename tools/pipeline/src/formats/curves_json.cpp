#include "curves_json.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string_view>
#include <vector>

#include "fapc/codec/fap_table.hpp"

namespace fapc::pipeline::builtin {

namespace {

// Room for any number below: "%.10g" never takes more than 17 characters ("-1.234567891e-308").
constexpr std::size_t kNumberRoom = 32;

// Ten significant digits: far below any tolerance of the data, and golden files do not change
// with the last bits of a sine between compilers. std::to_chars with a precision prints what
// printf's "%.10g" prints (the standard defines it so), without printf's cost per number. An
// integer below 10^10 prints under "%.10g" as the integer itself, and integer formatting costs
// a twentieth of it: FAP values are integers, and so are many times and values of scripts.
char* write_number(char* out, double v) {
  if (v == std::trunc(v) && std::abs(v) < 1e10 && !(v == 0 && std::signbit(v)))  // "-0" stays "-0"
    return std::to_chars(out, out + kNumberRoom, static_cast<std::int64_t>(v)).ptr;
  return std::to_chars(out, out + kNumberRoom, v, std::chars_format::general, 10).ptr;
}

char* write_text(char* out, std::string_view text) { return std::copy(text.begin(), text.end(), out); }

// One point, "[t, v]", with the ", " before it unless it is its list's first.
char* write_point(char* out, bool first, double t, double v) {
  if (!first) out = write_text(out, ", ");
  *out++ = '[';
  out = write_number(out, t);
  out = write_text(out, ", ");
  out = write_number(out, v);
  *out++ = ']';
  return out;
}

std::string header(int fps, double duration) {
  char number[kNumberRoom];
  return "{\n \"fps\": " + std::to_string(fps) +
         ",\n \"duration\": " + std::string(number, write_number(number, duration)) + ",\n \"curves\": {";
}

// Before each target: a line of its own, one target per line (golden files' diffs stay readable).
std::string target_opening(bool first, const std::string& target) {
  return std::string(first ? "\n" : ",\n") + "  " + nlohmann::json(target).dump() + ": [";
}

constexpr std::string_view kClosing = "\n }\n}\n";

// What a frame shows of FAP `fap` (masked there): its value, the select1 number for FAP 1 and 2.
std::int64_t frame_value(const FapFrame& frame, int fap) {
  if (fap == 1) return frame.viseme.select1;
  if (fap == 2) return frame.expression.select1;
  return frame.value(fap);
}

double frame_time(const FapSequence& sequence, const FapFrame& frame) {
  return static_cast<double>(frame.number) / sequence.fps;
}

}  // namespace

std::string curves_json(const Curves& curves) {
  std::string out = header(curves.fps, curves.duration);
  bool first_target = true;
  for (const auto& [target, points] : curves.curves) {
    out += target_opening(first_target, target);
    first_target = false;
    char point[2 * kNumberRoom + 8];
    for (std::size_t i = 0; i < points.size(); ++i)
      out.append(point, write_point(point, i == 0, points[i].first, points[i].second));
    out += ']';
  }
  out += kClosing;
  return out;
}

std::string frames_curves_json(const FapSequence& sequence) {
  // First pass: how many points each FAP has and how many characters they take.
  std::array<std::size_t, kFapCount + 1> points{};
  std::array<std::size_t, kFapCount + 1> point_bytes{};
  char time[kNumberRoom];
  char value[kNumberRoom];
  for (const FapFrame& frame : sequence.frames) {
    const auto time_size = static_cast<std::size_t>(write_number(time, frame_time(sequence, frame)) - time);
    for (int fap = 1; fap <= kFapCount; ++fap) {
      if (!frame.has(fap)) continue;
      const auto value_size =
          static_cast<std::size_t>(std::to_chars(value, value + kNumberRoom, frame_value(frame, fap)).ptr - value);
      ++points[static_cast<std::size_t>(fap)];
      point_bytes[static_cast<std::size_t>(fap)] += time_size + value_size + 4;  // "[", ", ", "]"
    }
  }

  // The targets in name order (a JSON object's keys as the script curves' map orders them).
  std::vector<std::pair<std::string, int>> targets;
  for (int fap = 1; fap <= kFapCount; ++fap)
    if (points[static_cast<std::size_t>(fap)] > 0) targets.emplace_back(find_fap(fap)->name, fap);
  std::sort(targets.begin(), targets.end());

  // The whole text's layout: each target's points get a stretch of their own, written in place.
  std::string out = header(sequence.fps, sequence.duration_seconds());
  std::vector<std::string> openings;
  std::size_t size = out.size() + kClosing.size();
  for (std::size_t k = 0; k < targets.size(); ++k) {
    const auto fap = static_cast<std::size_t>(targets[k].second);
    openings.push_back(target_opening(k == 0, targets[k].first));
    size += openings.back().size() + point_bytes[fap] + 2 * (points[fap] - 1) + 1;  // ", " between, "]"
  }
  std::array<char*, kFapCount + 1> cursor{};
  std::array<char*, kFapCount + 1> start{};
  const std::size_t header_size = out.size();
  out.resize(size);
  char* at = out.data() + header_size;
  for (std::size_t k = 0; k < targets.size(); ++k) {
    const auto fap = static_cast<std::size_t>(targets[k].second);
    at = write_text(at, openings[k]);
    start[fap] = cursor[fap] = at;
    at += point_bytes[fap] + 2 * (points[fap] - 1);
    *at++ = ']';
  }
  write_text(at, kClosing);

  // Second pass: each point written where its target's stretch has reached; "[t, " is the same
  // for every point of a frame, so it is made once per frame.
  char* const end = out.data() + out.size();
  char head[kNumberRoom + 3];
  for (const FapFrame& frame : sequence.frames) {
    char* head_end = head;
    *head_end++ = '[';
    head_end = write_number(head_end, frame_time(sequence, frame));
    head_end = write_text(head_end, ", ");
    for (int fap = 1; fap <= kFapCount; ++fap) {
      if (!frame.has(fap)) continue;
      char*& point = cursor[static_cast<std::size_t>(fap)];
      if (point != start[static_cast<std::size_t>(fap)]) point = write_text(point, ", ");
      point = std::copy(head, head_end, point);
      point = std::to_chars(point, end, frame_value(frame, fap)).ptr;
      *point++ = ']';
    }
  }
  return out;
}

}  // namespace fapc::pipeline::builtin
