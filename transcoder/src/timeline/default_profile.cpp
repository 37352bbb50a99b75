// The bundled profile (docs/profiles.md explains each scale): every free parameter name used in
// the Mimic paper's examples, plus the obvious companions (head_rot_z, lookat_y).
#include "fapc/transcoder/profile.hpp"

namespace fapc {
namespace {

// Scales: jaw and eyelids are fractions of a full movement (1 = one MNS of jaw drop, one iris
// diameter of lid travel: 1024 units each); head rotations are degrees (1 degree = pi/180 rad =
// 1745.329 AU of 1e-5 rad); gaze is a percentage of a 30 degree turn (523.599 AU per percent).
constexpr std::string_view kDefaultProfile = R"(# fapc default profile: name fap scale
jaw            open_jaw           1024
eyelid_left    close_t_l_eyelid   1024
eyelid_right   close_t_r_eyelid   1024
head_rot_x     head_pitch         1745.329
head_rot_y     head_yaw           1745.329
head_rot_z     head_roll          1745.329
lookat_x       yaw_l_eyeball      523.599
lookat_x       yaw_r_eyeball      523.599
lookat_y       pitch_l_eyeball    523.599
lookat_y       pitch_r_eyeball    523.599
)";

}  // namespace

std::string_view default_profile_text() { return kDefaultProfile; }

const Profile& default_profile() {
  // The text is part of the program and tested, so a parse failure cannot happen at run time.
  static const Profile profile = [] {
    Result<Profile> parsed = parse_profile(kDefaultProfile, "default");
    return parsed ? *parsed : Profile{"default", {}};
  }();
  return profile;
}

}  // namespace fapc
