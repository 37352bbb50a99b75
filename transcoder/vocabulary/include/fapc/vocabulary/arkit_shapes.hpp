// The names of ARKit's 52 face blendshapes: a fact of Apple's API that the Live Link Face app (in
// PascalCase, EyeBlinkLeft) and MediaPipe's face landmarker (camelCase, eyeBlinkLeft, plus its
// `_neutral`) both use.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>

namespace fapc::vocabulary {

inline constexpr int kArkitShapeCount = 52;

// In camelCase, in the column order of Live Link Face's CSV (its writer keeps that order).
const std::array<std::string_view, kArkitShapeCount>& arkit_shape_names();

// The shape's index, whichever case its first letter has ("EyeBlinkLeft", "eyeBlinkLeft"); nullopt
// for anything else (MediaPipe's "_neutral" included: it is not a shape).
std::optional<int> find_arkit_shape(std::string_view name);

// "EyeBlinkLeft": the spelling of Live Link Face's header.
std::string pascal_case(std::string_view camel);

}  // namespace fapc::vocabulary
