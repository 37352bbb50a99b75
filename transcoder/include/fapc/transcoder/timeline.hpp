// The shared timeline (docs/timeline.md): what every front end lowers to and the
// only thing that is rendered, encoded or written. Plain values, no I/O.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "fapc/codec/diagnostic.hpp"
#include "fapc/transcoder/audio.hpp"

namespace fapc {

// How a curve goes from one key point to the next. sin/log/exp are the Mimic fading functions
// f(u) on the fraction u of the segment elapsed: value = a + (b - a) * f(u).
enum class Interpolation { linear, step, sin, log, exp };

struct KeyPoint {
  double time = 0;  // seconds from the clip's begin
  double value = 0;
  Interpolation to_next = Interpolation::linear;  // the segment that starts here
  friend bool operator==(const KeyPoint&, const KeyPoint&) = default;
};

// A periodic function of the time since the clip's begin, starting at `min`:
// sine: min + (max - min) * (1 - cos(2 pi t / period)) / 2; triangle: min at 0, max at period / 2.
struct Periodic {
  enum class Shape { sine, triangle };
  Shape shape = Shape::sine;
  double min = 0;
  double max = 0;
  double period = 1;
  friend bool operator==(const Periodic&, const Periodic&) = default;
};

// Key points (times ascending, at least one) or a periodic function. Before the first key the
// curve takes the first value, after the last key the last value: the clip's interval decides
// where the curve counts.
struct Curve {
  std::vector<KeyPoint> keys;
  std::optional<Periodic> periodic;

  static Curve constant(double value);
  static Curve ramp(double from, double to, double duration, Interpolation how);
  double value_at(double local_time) const;
  // The limit from the left: at a jump (two keys at one time) the earlier key's side.
  double left_limit(double local_time) const;
  friend bool operator==(const Curve&, const Curve&) = default;
};

enum class BlendMode { add, average, overwrite };
// remove: the clip stops contributing at its end. freeze: it keeps its value at its end until the
// next clip of the same target begins (at or after that end).
enum class Fill { remove, freeze };

struct Clip {
  // The animation parameter: a standard FAP name ("open_jaw"), "viseme.<name>" / "expression.<name>"
  // (FAP 1 / FAP 2 weights 0..63, names from fap_table.hpp), or a free name that a Profile maps.
  std::string target;
  double begin = 0;  // active interval [begin, end), absolute seconds
  double end = 0;
  // The curve's local time at `begin` (non-zero when a clip's start was cut, e.g. by a repeat).
  double curve_offset = 0;
  Curve curve;
  BlendMode blend = BlendMode::add;
  Fill fill = Fill::remove;
  Location source;  // for warnings and per-clip plots

  double local_time(double t) const { return t - begin + curve_offset; }
};

// Clips in source order: ties between overwrite clips that begin together go to the later one.
struct Timeline {
  std::vector<Clip> clips;
  // The end of the animation when the source states it (e.g. --duration); else the latest clip end.
  std::optional<double> explicit_end;
  // Where explicit_end comes from (the element that ends last), for errors about the length.
  Location end_source = {};
  // Speech and recordings placed on the same clock as the clips (AudioClip::begin).
  std::vector<AudioClip> audio = {};

  double end() const;
};

const char* to_string(Interpolation how);
const char* to_string(BlendMode mode);
const char* to_string(Fill fill);

// A readable, stable text dump, one clip per line, for tests and `fapc compile --dump-timeline`.
std::string dump(const Timeline& timeline);

}  // namespace fapc
