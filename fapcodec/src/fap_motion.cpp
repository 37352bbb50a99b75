#include "fapc/codec/fap_motion.hpp"

#include <array>

#include "fapc/codec/fap_table.hpp"

namespace fapc {

namespace {

constexpr FapAction T = FapAction::translation;
constexpr FapAction R = FapAction::rotation;
constexpr FapAction D = FapAction::dilation;

// Directions of the standard's "positive motion" column in face coordinates (see the header):
// up = +y, down = -y, left (the face's own) = +x, right = -x, forward = +z. Rotations use the
// right-hand rule about the axis: +y turns the gaze to the face's left, +x turns it down, +z tilts
// the top of the head to the face's right; each matches its FAP's positive motion.
#define UP \
  { 0, 1, 0 }
#define DOWN \
  { 0, -1, 0 }
#define LEFT \
  { 1, 0, 0 }
#define RIGHT \
  { -1, 0, 0 }
#define FORWARD \
  { 0, 0, 1 }

constexpr std::array<FapMotion, kFapCount> kMotions{{
    {1, "", FapAction::none, {0, 0, 0}},
    {2, "", FapAction::none, {0, 0, 0}},
    {3, "2.1", T, DOWN},
    {4, "2.2", T, DOWN},
    {5, "2.3", T, UP},
    {6, "2.4", T, LEFT},
    {7, "2.5", T, RIGHT},
    {8, "2.6", T, DOWN},
    {9, "2.7", T, DOWN},
    {10, "2.8", T, UP},
    {11, "2.9", T, UP},
    {12, "2.4", T, UP},
    {13, "2.5", T, UP},
    {14, "2.1", T, FORWARD},
    {15, "2.1", T, RIGHT},
    {16, "2.3", T, FORWARD},
    {17, "2.2", T, FORWARD},
    {18, "2.10", T, UP},
    {19, "3.1", T, DOWN},
    {20, "3.2", T, DOWN},
    {21, "3.3", T, UP},
    {22, "3.4", T, UP},
    {23, "3.5", R, {0, 1, 0}},  // yaw_l_eyeball: positive turns left
    {24, "3.6", R, {0, 1, 0}},  // yaw_r_eyeball: positive turns left too
    {25, "3.5", R, {1, 0, 0}},  // pitch: positive turns down
    {26, "3.6", R, {1, 0, 0}},
    {27, "3.5", T, FORWARD},
    {28, "3.6", T, FORWARD},
    {29, "3.5", D, {0, 0, 0}},
    {30, "3.6", D, {0, 0, 0}},
    {31, "4.1", T, UP},
    {32, "4.2", T, UP},
    {33, "4.3", T, UP},
    {34, "4.4", T, UP},
    {35, "4.5", T, UP},
    {36, "4.6", T, UP},
    {37, "4.1", T, RIGHT},
    {38, "4.2", T, LEFT},  // squeeze: towards the nose
    {39, "5.1", T, LEFT},
    {40, "5.2", T, RIGHT},
    {41, "5.3", T, UP},
    {42, "5.4", T, UP},
    {43, "6.1", T, RIGHT},
    {44, "6.1", T, UP},
    {45, "6.1", T, FORWARD},
    {46, "6.2", T, UP},
    {47, "6.3", R, {0, 0, 1}},  // tongue_roll: about the tongue's length (6.3 and 6.4)
    {48, "7.1", R, {1, 0, 0}},  // head_pitch: positive nods down
    {49, "7.1", R, {0, 1, 0}},  // head_yaw: positive turns left
    {50, "7.1", R, {0, 0, 1}},  // head_roll: positive tilts right
    {51, "8.1", T, DOWN},
    {52, "8.2", T, UP},
    {53, "8.3", T, LEFT},
    {54, "8.4", T, RIGHT},
    {55, "8.5", T, DOWN},
    {56, "8.6", T, DOWN},
    {57, "8.7", T, UP},
    {58, "8.8", T, UP},
    {59, "8.3", T, UP},
    {60, "8.4", T, UP},
    {61, "9.1", T, LEFT},
    {62, "9.2", T, RIGHT},
    {63, "9.3", T, UP},
    {64, "9.3", T, RIGHT},
    {65, "10.1", T, UP},
    {66, "10.2", T, UP},
    {67, "10.3", T, LEFT},
    {68, "10.4", T, RIGHT},
}};

#undef UP
#undef DOWN
#undef LEFT
#undef RIGHT
#undef FORWARD

}  // namespace

const FapMotion* fap_motion(int number) {
  if (number < 1 || number > kFapCount) return nullptr;
  return &kMotions[static_cast<std::size_t>(number - 1)];
}

}  // namespace fapc
