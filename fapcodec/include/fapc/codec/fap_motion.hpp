// Where each FAP acts: the feature point it moves and the direction a positive value moves it, as
// the standard's FAP table gives them (FDP point column and "positive motion"; see
// docs/render.md). Part of the FAP table, kept in its own file so that renderers can use it without
// the codec's other facts.
#pragma once

#include <string_view>

namespace fapc {

// How a FAP's value acts on its feature point.
enum class FapAction {
  none,         // FAP 1 and 2: high-level, no point of their own
  translation,  // moves the point by value x FAPU along `direction`
  rotation,     // turns about `direction` (the axis) by value x AU: eyeballs, head, tongue roll
  dilation,     // grows the pupil's diameter by value x IRISD
};

// Face coordinates of the standard's neutral face: x towards the face's own left, y up, z forward
// (out of the face, towards a viewer who looks at it). Right-handed.
struct FapMotion {
  int number;                      // 1..68
  std::string_view feature_point;  // "2.1"; empty for FAP 1 and 2
  FapAction action;
  int direction[3];  // unit axis in face coordinates (translation or rotation axis)
};

// The motion of FAP `number` (1..68), or null.
const FapMotion* fap_motion(int number);

}  // namespace fapc
