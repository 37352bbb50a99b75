// What an `animate` or `set` element does to its attribute over one simple duration: SMIL's
// animation function (values, keyTimes, calcMode, additive, accumulate; from/to/by reduce to
// values), and the timeline curve of each run (docs/xmt-omega.md, "Values").
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "fapc/timeline/timeline.hpp"
#include "fapc/xml/xml_document.hpp"

namespace fapc::xmto {

enum class CalcMode { linear, discrete, paced };

// An animation function without its numbers (values and key times), which a reader of many
// elements keeps in one pool (XmtoTree::numbers) rather than in two vectors per element.
struct AnimationShape {
  CalcMode calc = CalcMode::linear;
  bool to_animation = false;  // from the underlying value at the run's begin to values.back()
  bool accumulate = false;    // run k adds k times the last value
  BlendMode blend = BlendMode::overwrite;
  // dur; empty: the simple duration is indefinite and the first value holds (SMIL).
  std::optional<double> simple_duration;
};

struct AnimationFunction : AnimationShape {
  // For a to-animation values[0] stands for the underlying value, known only when placed.
  std::vector<double> values;
  std::vector<double> key_times;  // fractions of the simple duration, one per value; may be empty
};

// The curve of one run. `underlying` replaces values[0] of a to-animation; `iteration` is the
// run's repeat index (accumulate).
Curve animation_curve(const AnimationShape& shape, std::span<const double> values, std::span<const double> key_times,
                      double underlying, int iteration);

// Reads from/to/by/values/keyTimes/calcMode/additive/accumulate of an `animate` (warnings for
// attributes SMIL says are ignored in that combination), or `to` of a `set`. Errors at the
// attribute. `dur` comes from the element's timing.
Result<AnimationFunction> read_animate(const xml::XmlDocument& doc, const xmlNode* element, std::optional<double> dur,
                                       Diagnostics& warnings);
Result<AnimationFunction> read_set(const xml::XmlDocument& doc, const xmlNode* element, std::optional<double> dur);

}  // namespace fapc::xmto
