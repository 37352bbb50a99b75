#include "fapc/vocabulary/arkit_shapes.hpp"

#include <cctype>

namespace fapc::vocabulary {

const std::array<std::string_view, kArkitShapeCount>& arkit_shape_names() {
  static constexpr std::array<std::string_view, kArkitShapeCount> names{
      "eyeBlinkLeft",
      "eyeLookDownLeft",
      "eyeLookInLeft",
      "eyeLookOutLeft",
      "eyeLookUpLeft",
      "eyeSquintLeft",
      "eyeWideLeft",
      "eyeBlinkRight",
      "eyeLookDownRight",
      "eyeLookInRight",
      "eyeLookOutRight",
      "eyeLookUpRight",
      "eyeSquintRight",
      "eyeWideRight",
      "jawForward",
      "jawRight",
      "jawLeft",
      "jawOpen",
      "mouthClose",
      "mouthFunnel",
      "mouthPucker",
      "mouthRight",
      "mouthLeft",
      "mouthSmileLeft",
      "mouthSmileRight",
      "mouthFrownLeft",
      "mouthFrownRight",
      "mouthDimpleLeft",
      "mouthDimpleRight",
      "mouthStretchLeft",
      "mouthStretchRight",
      "mouthRollLower",
      "mouthRollUpper",
      "mouthShrugLower",
      "mouthShrugUpper",
      "mouthPressLeft",
      "mouthPressRight",
      "mouthLowerDownLeft",
      "mouthLowerDownRight",
      "mouthUpperUpLeft",
      "mouthUpperUpRight",
      "browDownLeft",
      "browDownRight",
      "browInnerUp",
      "browOuterUpLeft",
      "browOuterUpRight",
      "cheekPuff",
      "cheekSquintLeft",
      "cheekSquintRight",
      "noseSneerLeft",
      "noseSneerRight",
      "tongueOut",
  };
  return names;
}

std::optional<int> find_arkit_shape(std::string_view name) {
  if (name.empty()) return std::nullopt;
  const auto& names = arkit_shape_names();
  for (int i = 0; i < kArkitShapeCount; ++i) {
    const std::string_view candidate = names[static_cast<std::size_t>(i)];
    if (candidate.size() == name.size() && candidate.substr(1) == name.substr(1) &&
        std::tolower(static_cast<unsigned char>(name[0])) == candidate[0]) {
      return i;
    }
  }
  return std::nullopt;
}

std::string pascal_case(std::string_view camel) {
  std::string out(camel);
  if (!out.empty()) out[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(out[0])));
  return out;
}

}  // namespace fapc::vocabulary
