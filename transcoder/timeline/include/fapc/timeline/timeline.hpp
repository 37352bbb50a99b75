// The shared timeline (docs/timeline.md): what every front end lowers to and the
// only thing that is rendered, encoded or written. Plain values, no I/O.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "fapc/codec/diagnostic.hpp"
#include "fapc/timeline/audio.hpp"
#include "fapc/timeline/target_name.hpp"

namespace fapc::timeline {

// How a curve goes from one key point to the next. sin/log/exp are the Mimic fading functions
// f(u) on the fraction u of the segment elapsed: value = a + (b - a) * f(u).
enum class Interpolation : std::uint8_t { linear, step, sin, log, exp };

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

// std::optional<Periodic> kept off the clip: few clips are periodic, and in place the function
// would cost every clip 40 bytes; here it costs 8, and a periodic clip one small allocation.
// Reads and assigns like the optional.
class OptionalPeriodic {
 public:
  OptionalPeriodic() = default;
  OptionalPeriodic(std::nullopt_t) {}                                                                         // NOLINT
  OptionalPeriodic(const Periodic& p) : box_(std::make_unique<Periodic>(p)) {}                                // NOLINT
  OptionalPeriodic(const std::optional<Periodic>& p) : box_(p ? std::make_unique<Periodic>(*p) : nullptr) {}  // NOLINT
  OptionalPeriodic(const OptionalPeriodic& other) : OptionalPeriodic(other.as_optional()) {}
  OptionalPeriodic(OptionalPeriodic&&) noexcept = default;
  OptionalPeriodic& operator=(const OptionalPeriodic& other) {
    if (this != &other) box_ = other.box_ ? std::make_unique<Periodic>(*other.box_) : nullptr;
    return *this;
  }
  OptionalPeriodic& operator=(OptionalPeriodic&&) noexcept = default;

  explicit operator bool() const { return box_ != nullptr; }
  bool has_value() const { return box_ != nullptr; }
  const Periodic& operator*() const { return *box_; }
  Periodic& operator*() { return *box_; }
  const Periodic* operator->() const { return box_.get(); }
  Periodic* operator->() { return box_.get(); }
  void reset() { box_.reset(); }
  std::optional<Periodic> as_optional() const { return box_ ? std::optional<Periodic>(*box_) : std::nullopt; }

  friend bool operator==(const OptionalPeriodic& a, const OptionalPeriodic& b) {
    return a.box_ && b.box_ ? *a.box_ == *b.box_ : a.box_ == b.box_;
  }

 private:
  std::unique_ptr<Periodic> box_;
};

// Key points (times ascending, at least one) or a periodic function. Before the first key the
// curve takes the first value, after the last key the last value: the clip's interval decides
// where the curve counts.
struct Curve {
  std::vector<KeyPoint> keys;
  OptionalPeriodic periodic;

  static Curve constant(double value);
  static Curve ramp(double from, double to, double duration, Interpolation how);
  double value_at(double local_time) const;
  // The limit from the left: at a jump (two keys at one time) the earlier key's side.
  double left_limit(double local_time) const;
  friend bool operator==(const Curve&, const Curve&) = default;
};

enum class BlendMode : std::uint8_t { add, average, overwrite };
// remove: the clip stops contributing at its end. freeze: it keeps its value at its end until the
// next clip of the same target begins (at or after that end).
enum class Fill : std::uint8_t { remove, freeze };

// 96 bytes (and the curve's key points): a script of a million elements has a million clips.
struct Clip {
  // The animation parameter: a standard FAP name ("open_jaw"), "viseme.<name>" / "expression.<name>"
  // (FAP 1 / FAP 2 weights 0..63, names from fap_table.hpp), or a free name that a Profile maps.
  TargetName target;
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

}  // namespace fapc::timeline

// Until the tree names the model fapc::timeline::..., the names are seen from fapc as before.
namespace fapc {
using namespace timeline;
}  // namespace fapc
