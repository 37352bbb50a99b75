#include "fapc/codec/fap_table.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>

namespace fapc {

namespace {

// Transcribed from the standard's FAP table (docs/fap-table.md): number, name, description,
// unit, bidirectional, positive motion, group, QP, default I range, default P range.
constexpr std::array<FapInfo, kFapCount> kFaps{{
    {1, "viseme", "high level: blend of two visemes", Fapu::none, false, "", 1, 1, 0, 0},
    {2, "expression", "high level: blend of two expressions", Fapu::none, false, "", 1, 1, 0, 0},
    {3, "open_jaw", "vertical jaw displacement (does not affect mouth opening)", Fapu::mns, false, "down", 2, 4, 1080,
     360},
    {4, "lower_t_midlip", "vertical top middle inner lip displacement", Fapu::mns, true, "down", 2, 2, 600, 180},
    {5, "raise_b_midlip", "vertical bottom middle inner lip displacement", Fapu::mns, true, "up", 2, 2, 1860, 600},
    {6, "stretch_l_cornerlip", "horizontal displacement of left inner lip corner", Fapu::mw, true, "left", 2, 2, 600,
     180},
    {7, "stretch_r_cornerlip", "horizontal displacement of right inner lip corner", Fapu::mw, true, "right", 2, 2, 600,
     180},
    {8, "lower_t_lip_lm", "vertical displacement of midpoint between left corner and middle of top inner lip",
     Fapu::mns, true, "down", 2, 2, 600, 180},
    {9, "lower_t_lip_rm", "vertical displacement of midpoint between right corner and middle of top inner lip",
     Fapu::mns, true, "down", 2, 2, 600, 180},
    {10, "raise_b_lip_lm", "vertical displacement of midpoint between left corner and middle of bottom inner lip",
     Fapu::mns, true, "up", 2, 2, 1860, 600},
    {11, "raise_b_lip_rm", "vertical displacement of midpoint between right corner and middle of bottom inner lip",
     Fapu::mns, true, "up", 2, 2, 1860, 600},
    {12, "raise_l_cornerlip", "vertical displacement of left inner lip corner", Fapu::mns, true, "up", 2, 2, 600, 180},
    {13, "raise_r_cornerlip", "vertical displacement of right inner lip corner", Fapu::mns, true, "up", 2, 2, 600, 180},
    {14, "thrust_jaw", "depth displacement of jaw", Fapu::mns, false, "forward", 2, 1, 600, 180},
    {15, "shift_jaw", "side-to-side displacement of jaw", Fapu::mw, true, "right", 2, 1, 1080, 360},
    {16, "push_b_lip", "depth displacement of bottom middle lip", Fapu::mns, true, "forward", 2, 1, 1080, 360},
    {17, "push_t_lip", "depth displacement of top middle lip", Fapu::mns, true, "forward", 2, 1, 1080, 360},
    {18, "depress_chin", "upward and compressing movement of the chin", Fapu::mns, true, "up", 2, 1, 420, 180},
    {19, "close_t_l_eyelid", "vertical displacement of top left eyelid", Fapu::irisd, true, "down", 3, 1, 1080, 600},
    {20, "close_t_r_eyelid", "vertical displacement of top right eyelid", Fapu::irisd, true, "down", 3, 1, 1080, 600},
    {21, "close_b_l_eyelid", "vertical displacement of bottom left eyelid", Fapu::irisd, true, "up", 3, 1, 600, 240},
    {22, "close_b_r_eyelid", "vertical displacement of bottom right eyelid", Fapu::irisd, true, "up", 3, 1, 600, 240},
    {23, "yaw_l_eyeball", "horizontal orientation of left eyeball", Fapu::au, true, "left", 3, 128, 1200, 420},
    {24, "yaw_r_eyeball", "horizontal orientation of right eyeball", Fapu::au, true, "left", 3, 128, 1200, 420},
    {25, "pitch_l_eyeball", "vertical orientation of left eyeball", Fapu::au, true, "down", 3, 128, 900, 300},
    {26, "pitch_r_eyeball", "vertical orientation of right eyeball", Fapu::au, true, "down", 3, 128, 900, 300},
    {27, "thrust_l_eyeball", "depth displacement of left eyeball", Fapu::es, true, "forward", 3, 1, 600, 180},
    {28, "thrust_r_eyeball", "depth displacement of right eyeball", Fapu::es, true, "forward", 3, 1, 600, 180},
    {29, "dilate_l_pupil", "dilation of left pupil", Fapu::irisd, true, "growing", 3, 1, 420, 120},
    {30, "dilate_r_pupil", "dilation of right pupil", Fapu::irisd, true, "growing", 3, 1, 420, 120},
    {31, "raise_l_i_eyebrow", "vertical displacement of left inner eyebrow", Fapu::ens, true, "up", 4, 2, 900, 360},
    {32, "raise_r_i_eyebrow", "vertical displacement of right inner eyebrow", Fapu::ens, true, "up", 4, 2, 900, 360},
    {33, "raise_l_m_eyebrow", "vertical displacement of left middle eyebrow", Fapu::ens, true, "up", 4, 2, 900, 360},
    {34, "raise_r_m_eyebrow", "vertical displacement of right middle eyebrow", Fapu::ens, true, "up", 4, 2, 900, 360},
    {35, "raise_l_o_eyebrow", "vertical displacement of left outer eyebrow", Fapu::ens, true, "up", 4, 2, 900, 360},
    {36, "raise_r_o_eyebrow", "vertical displacement of right outer eyebrow", Fapu::ens, true, "up", 4, 2, 900, 360},
    {37, "squeeze_l_eyebrow", "horizontal displacement of left eyebrow", Fapu::es, true, "right", 4, 1, 900, 300},
    {38, "squeeze_r_eyebrow", "horizontal displacement of right eyebrow", Fapu::es, true, "left", 4, 1, 900, 300},
    {39, "puff_l_cheek", "horizontal displacement of left cheek", Fapu::es, true, "left", 5, 2, 900, 300},
    {40, "puff_r_cheek", "horizontal displacement of right cheek", Fapu::es, true, "right", 5, 2, 900, 300},
    {41, "lift_l_cheek", "vertical displacement of left cheek", Fapu::ens, false, "up", 5, 2, 600, 180},
    {42, "lift_r_cheek", "vertical displacement of right cheek", Fapu::ens, false, "up", 5, 2, 600, 180},
    {43, "shift_tongue_tip", "horizontal displacement of tongue tip", Fapu::mw, true, "right", 6, 1, 1080, 420},
    {44, "raise_tongue_tip", "vertical displacement of tongue tip", Fapu::mns, true, "up", 6, 1, 1080, 420},
    {45, "thrust_tongue_tip", "depth displacement of tongue tip", Fapu::mw, true, "forward", 6, 1, 1080, 420},
    {46, "raise_tongue", "vertical displacement of tongue", Fapu::mns, true, "up", 6, 1, 1080, 420},
    {47, "tongue_roll", "rolling of the tongue into U shape", Fapu::au, false, "concave upward", 6, 512, 1080, 420},
    {48, "head_pitch", "head pitch angle from top of spine", Fapu::au, true, "down", 7, 170, 1860, 600},
    {49, "head_yaw", "head yaw angle from top of spine", Fapu::au, true, "left", 7, 170, 1860, 600},
    {50, "head_roll", "head roll angle from top of spine", Fapu::au, true, "right", 7, 170, 1860, 600},
    {51, "lower_t_midlip_o", "vertical top middle outer lip displacement", Fapu::mns, true, "down", 8, 2, 600, 180},
    {52, "raise_b_midlip_o", "vertical bottom middle outer lip displacement", Fapu::mns, true, "up", 8, 2, 1860, 600},
    {53, "stretch_l_cornerlip_o", "horizontal displacement of left outer lip corner", Fapu::mw, true, "left", 8, 2, 600,
     180},
    {54, "stretch_r_cornerlip_o", "horizontal displacement of right outer lip corner", Fapu::mw, true, "right", 8, 2,
     600, 180},
    {55, "lower_t_lip_lm_o", "vertical displacement of midpoint between left corner and middle of top outer lip",
     Fapu::mns, true, "down", 8, 2, 600, 180},
    {56, "lower_t_lip_rm_o", "vertical displacement of midpoint between right corner and middle of top outer lip",
     Fapu::mns, true, "down", 8, 2, 600, 180},
    {57, "raise_b_lip_lm_o", "vertical displacement of midpoint between left corner and middle of bottom outer lip",
     Fapu::mns, true, "up", 8, 2, 1860, 600},
    {58, "raise_b_lip_rm_o", "vertical displacement of midpoint between right corner and middle of bottom outer lip",
     Fapu::mns, true, "up", 8, 2, 1860, 600},
    {59, "raise_l_cornerlip_o", "vertical displacement of left outer lip corner", Fapu::mns, true, "up", 8, 2, 600,
     180},
    {60, "raise_r_cornerlip_o", "vertical displacement of right outer lip corner", Fapu::mns, true, "up", 8, 2, 600,
     180},
    {61, "stretch_l_nose", "horizontal displacement of left side of nose", Fapu::ens, true, "left", 9, 1, 540, 120},
    {62, "stretch_r_nose", "horizontal displacement of right side of nose", Fapu::ens, true, "right", 9, 1, 540, 120},
    {63, "raise_nose", "vertical displacement of nose tip", Fapu::ens, true, "up", 9, 1, 680, 180},
    {64, "bend_nose", "horizontal displacement of nose tip", Fapu::ens, true, "right", 9, 1, 900, 180},
    {65, "raise_l_ear", "vertical displacement of left ear", Fapu::ens, true, "up", 10, 1, 900, 240},
    {66, "raise_r_ear", "vertical displacement of right ear", Fapu::ens, true, "up", 10, 1, 900, 240},
    {67, "pull_l_ear", "horizontal displacement of left ear", Fapu::ens, true, "left", 10, 1, 900, 300},
    {68, "pull_r_ear", "horizontal displacement of right ear", Fapu::ens, true, "right", 10, 1, 900, 300},
}};

constexpr std::array<FapuInfo, 7> kFapus{{
    {Fapu::none, "na", "no unit (FAP 1 and FAP 2 carry their own fields)"},
    {Fapu::irisd, "IRISD", "iris diameter / 1024 (distance between upper and lower eyelid)"},
    {Fapu::es, "ES", "eye separation / 1024 (between the pupil centres)"},
    {Fapu::ens, "ENS", "eye-nose separation / 1024"},
    {Fapu::mns, "MNS", "mouth-nose separation / 1024"},
    {Fapu::mw, "MW", "mouth width / 1024"},
    {Fapu::au, "AU", "angle unit, 1e-5 rad"},
}};

constexpr std::array<FapGroup, kFapGroupCount> kGroups{{
    {1, 1, 2, "visemes and expressions"},
    {2, 3, 18, "jaw, chin, inner lip"},
    {3, 19, 30, "eyeballs, pupils, eyelids"},
    {4, 31, 38, "eyebrows"},
    {5, 39, 42, "cheeks"},
    {6, 43, 47, "tongue"},
    {7, 48, 50, "head rotation"},
    {8, 51, 60, "outer lips"},
    {9, 61, 64, "nose"},
    {10, 65, 68, "ears"},
}};

constexpr std::array<std::string_view, 15> kVisemes{"none", "PP", "FF", "TH", "DD", "kk", "CH", "SS",
                                                    "nn",   "RR", "AA", "E",  "ih", "oh", "ou"};
constexpr std::array<std::string_view, 7> kExpressions{"neutral", "joy",     "sadness", "anger",
                                                       "fear",    "disgust", "surprise"};

}  // namespace

int FapInfo::legal_max() const {
  const int rounded = (intra_range + 59) / 60 * 60;  // the reference decoder rounds up to 60s
  return number <= 2 ? 0 : rounded * quant_step;
}

const std::array<FapInfo, kFapCount>& fap_table() { return kFaps; }
const std::array<FapuInfo, 7>& fapu_table() { return kFapus; }
const std::array<FapGroup, kFapGroupCount>& fap_groups() { return kGroups; }

std::string_view fapu_name(Fapu unit) { return kFapus[static_cast<std::size_t>(unit)].name; }

const FapInfo* find_fap(int number) {
  if (number < 1 || number > kFapCount) return nullptr;
  return &kFaps[static_cast<std::size_t>(number - 1)];
}

const FapInfo* find_fap(std::string_view name) {
  for (const FapInfo& f : kFaps)
    if (f.name == name) return &f;
  return nullptr;
}

const FapInfo* find_fap_by_name_or_number(std::string_view text) {
  if (const FapInfo* f = find_fap(text)) return f;
  std::string_view digits = text;
  if (digits.size() > 3 && (digits.substr(0, 3) == "fap" || digits.substr(0, 3) == "FAP")) digits.remove_prefix(3);
  int number = 0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), number);
  if (ec != std::errc{} || end != digits.data() + digits.size()) return nullptr;
  return find_fap(number);
}

std::vector<std::string_view> closest_fap_names(std::string_view name, std::size_t how_many) {
  std::vector<std::string> names;
  for (const FapInfo& f : kFaps) names.emplace_back(f.name);
  std::vector<std::string_view> best;
  for (const std::string& n : closest_names(name, names, how_many)) best.push_back(find_fap(n)->name);
  return best;
}

std::string unknown_fap_message(std::string_view name) {
  std::vector<std::string> best;
  for (const std::string_view n : closest_fap_names(name)) best.emplace_back(n);
  const std::string unknown = "unknown FAP name " + quoted_name(name);
  return best.empty() ? unknown : unknown + "; did you mean " + or_list(best) + "?";
}

std::string_view viseme_name(int viseme) {
  return viseme >= 0 && viseme < 15 ? kVisemes[static_cast<std::size_t>(viseme)] : "?";
}
std::string_view expression_name(int expression) {
  return expression >= 0 && expression < 7 ? kExpressions[static_cast<std::size_t>(expression)] : "?";
}

}  // namespace fapc
