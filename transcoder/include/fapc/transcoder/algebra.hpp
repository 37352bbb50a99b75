// The Algebra of Expressions (docs/algebra.md, with the paper's definitions under "The paper"):
// facial states, animations, and the sum, amplifier and overlapper on both.
#pragma once

#include <array>
#include <bitset>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fapc/codec/diagnostic.hpp"
#include "fapc/codec/fap_sequence.hpp"
#include "fapc/transcoder/expression_file.hpp"
#include "fapc/transcoder/profile.hpp"

namespace fapc::algebra {

inline constexpr int kStateSize = 66;  // FAP 3 .. FAP 68

// Round to the nearest integer, halves away from zero (docs/algebra.md).
std::int32_t round_half_away(double x);

// 66 integers; element i is FAP i + 3.
struct FacialState {
  std::array<std::int32_t, kStateSize> values{};

  std::int32_t& at(int fap) { return values[static_cast<std::size_t>(fap - 3)]; }
  std::int32_t at(int fap) const { return values[static_cast<std::size_t>(fap - 3)]; }
  friend bool operator==(const FacialState&, const FacialState&) = default;
};

// S +_v T = round(s v) + round(t (1 - v)).
FacialState sum(const FacialState& s, const FacialState& t, double v);
// w S = round(w s).
FacialState amplify(const FacialState& s, double w);

// Which FAPs an overlap operand covers.
struct Mask {
  std::bitset<kStateSize> bits;
  static Mask all();
  bool covers(int fap) const { return bits.test(static_cast<std::size_t>(fap - 3)); }
  void set(int fap) { bits.set(static_cast<std::size_t>(fap - 3)); }
};
// "mouth", "brows,eyes", "3-18", "open_jaw,head", "all,!head": group names (docs/algebra.md),
// FAP names or numbers, ranges, `!` to take away. Errors give the 0-based offset in `message`.
Result<Mask> parse_mask(std::string_view text);
const std::vector<std::pair<std::string_view, std::vector<int>>>& mask_group_names();

// An overlap operand: a state seen through its mask, with a priority per FAP (operands have one
// priority; the result of an overlap keeps the winner's priority for each FAP, which is what
// makes nested overlaps associative).
struct Layer {
  FacialState state;
  std::array<int, kStateSize> priority{};

  static Layer of(const FacialState& s, const Mask& mask, int priority);
};
// g = s + t where s or t is 0, else the value of the higher priority; equal priorities where both
// are non-zero: an error (its message names the FAP).
Result<Layer> overlap(const Layer& a, const Layer& b);

// ---- animations -------------------------------------------------------------------------------

// States on a frame grid: frame k at time k / fps; empty slots are frames the animation lacks.
struct Animation {
  int fps = 25;
  std::vector<std::optional<FacialState>> frames;
  // The FAPs the inputs carried (their .fap masks), kept through the operators so that an
  // output's masks are as compact as its inputs'.
  std::bitset<kStateSize> carried;

  std::size_t size() const { return frames.size(); }
};

Animation animation_from(const FapSequence& sequence);  // unmasked FAPs read as 0
// Frames for the slots that hold a state; each frame's mask is `carried` plus its non-zero FAPs.
FapSequence sequence_from(const Animation& a, const std::string& name);

// The same animation on another frame grid: linear interpolation between neighbouring frames,
// rounded; slots between two missing frames stay empty.
Animation resample(const Animation& a, int fps);
// Delayed by `seconds` (whole frames at its own rate), earlier slots empty.
Animation shifted(const Animation& a, double seconds);
// Delayed by `frames` (>= 0) empty slots, in place: no copy of the frames already there.
void delay_in_place(Animation& a, long frames);

// Frame by frame on a common rate (the higher one): both present -> the operator; one present ->
// that state; neither -> the neutral state (Algebra definition 5, used for every operator).
Animation sum(const Animation& a, const Animation& b, double v);
Animation amplify(const Animation& a, double w);
struct LayeredAnimation {
  Animation animation;
  Mask mask;
  int priority = 0;
};
// A Ω B Ω ...: frame by frame, the operands present folded with the state overlapper (neutral
// where none is present). Errors name the time of the frame.
Result<Animation> overlap(const std::vector<LayeredAnimation>& operands);

// A state from `parameter value` entries (a .xpr file): each parameter resolved through the
// profile (FAP names need none), scaled into FAP units and rounded; errors at the entry.
Result<FacialState> state_from_entries(const std::vector<ExpressionEntry>& entries, const Profile& profile);

}  // namespace fapc::algebra
