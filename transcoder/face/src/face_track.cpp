#include "fapc/face/face_track.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace fapc::face {

namespace {

using Entry = std::pair<int, double>;  // FAP number, value in FAP units at full strength

FapValues from_entries(std::initializer_list<Entry> entries) {
  FapValues v{};
  for (const auto& [fap, value] : entries) v[static_cast<std::size_t>(fap - 1)] = value;
  return v;
}

// Mouth shapes of the standard's 14 visemes, fapc's own numbers (FAP units): jaw opening
// (3), lip stretch (6/7, 53/54), lip protrusion (16/17), lower lip (5), tongue (44-46).
const std::array<FapValues, 15>& visemes() {
  static const std::array<FapValues, 15> table{
      FapValues{},                                                       // none
      from_entries({{3, 40}, {4, 120}, {5, 160}, {51, 80}, {52, 120}}),  // PP: lips pressed
      from_entries({{3, 120}, {5, 300}, {52, 260}, {16, -100}}),         // FF: lower lip to teeth
      from_entries({{3, 220}, {45, 300}, {44, 150}}),                    // TH
      from_entries({{3, 240}, {44, 350}}),                               // DD
      from_entries({{3, 300}, {46, 300}}),                               // kk
      from_entries({{3, 200}, {6, -160}, {7, -160}, {53, -140}, {54, -140}, {16, 220}, {17, 220}}),  // CH
      from_entries({{3, 120}, {6, 120}, {7, 120}, {53, 100}, {54, 100}}),                            // SS
      from_entries({{3, 180}, {44, 350}}),                                                           // nn
      from_entries({{3, 220}, {6, -100}, {7, -100}, {16, 120}, {17, 120}}),                          // RR
      from_entries({{3, 700}, {5, -150}, {52, -150}, {4, -60}, {51, -60}}),                          // AA
      from_entries({{3, 420}, {6, 160}, {7, 160}, {53, 140}, {54, 140}}),                            // E
      from_entries({{3, 300}, {6, 220}, {7, 220}, {53, 200}, {54, 200}}),                            // ih
      from_entries({{3, 520}, {6, -260}, {7, -260}, {53, -240}, {54, -240}, {16, 160}, {17, 160}}),  // oh
      from_entries({{3, 260}, {6, -380}, {7, -380}, {53, -360}, {54, -360}, {16, 320}, {17, 320}}),  // ou
  };
  return table;
}

// The six expressions of the standard at full intensity, fapc's own numbers.
const std::array<FapValues, 7>& expressions() {
  static const std::array<FapValues, 7> table{
      FapValues{},  // neutral
      from_entries({{6, 180},
                    {7, 180},
                    {12, 220},
                    {13, 220},
                    {53, 160},
                    {54, 160},
                    {59, 200},
                    {60, 200},
                    {41, 200},
                    {42, 200},
                    {21, 150},
                    {22, 150}}),  // joy
      from_entries({{31, 260},
                    {32, 260},
                    {35, -120},
                    {36, -120},
                    {19, 250},
                    {20, 250},
                    {12, -180},
                    {13, -180},
                    {59, -160},
                    {60, -160}}),  // sadness
      from_entries({{31, -260},
                    {32, -260},
                    {33, -160},
                    {34, -160},
                    {37, 200},
                    {38, 200},
                    {19, -150},
                    {20, -150},
                    {4, 60},
                    {5, 60},
                    {12, -100},
                    {13, -100}}),  // anger
      from_entries({{31, 320},
                    {32, 320},
                    {33, 260},
                    {34, 260},
                    {35, 180},
                    {36, 180},
                    {19, -250},
                    {20, -250},
                    {3, 250},
                    {6, 160},
                    {7, 160}}),  // fear
      from_entries(
          {{51, -220}, {4, -180}, {63, 160}, {31, -120}, {32, -120}, {21, 220}, {22, 220}, {12, -80}}),  // disgust
      from_entries({{31, 420},
                    {32, 420},
                    {33, 460},
                    {34, 460},
                    {35, 380},
                    {36, 380},
                    {19, -300},
                    {20, -300},
                    {3, 600}}),  // surprise
  };
  return table;
}

void add_scaled(FapValues& to, const FapValues& from, double scale) {
  if (scale == 0) return;
  for (std::size_t i = 0; i < to.size(); ++i) to[i] += from[i] * scale;
}

}  // namespace

const FapValues& viseme_displacements(int viseme) {
  static const FapValues none{};
  return viseme >= 1 && viseme <= 14 ? visemes()[static_cast<std::size_t>(viseme)] : none;
}

const FapValues& expression_displacements(int expression) {
  static const FapValues none{};
  return expression >= 1 && expression <= 6 ? expressions()[static_cast<std::size_t>(expression)] : none;
}

FapValues high_level_values(const VisemeFields& viseme, bool has_viseme, const ExpressionFields& expression,
                            bool has_expression) {
  FapValues v{};
  if (has_viseme) {
    const double blend = std::clamp(viseme.blend, 0, 63) / 63.0;
    add_scaled(v, viseme_displacements(viseme.select1), blend);
    add_scaled(v, viseme_displacements(viseme.select2), 1 - blend);
  }
  if (has_expression) {
    add_scaled(v, expression_displacements(expression.select1), std::clamp(expression.intensity1, 0, 63) / 63.0);
    add_scaled(v, expression_displacements(expression.select2), std::clamp(expression.intensity2, 0, 63) / 63.0);
  }
  return v;
}

FaceTrack::FaceTrack(const FapSequence& sequence) : fps_(sequence.fps > 0 ? sequence.fps : 25) {
  FapValues held{};  // low-level values as last sent
  VisemeFields viseme;
  ExpressionFields expression;
  bool has_viseme = false, has_expression = false;
  numbers_.reserve(sequence.frames.size());
  shown_.reserve(sequence.frames.size());
  for (const FapFrame& frame : sequence.frames) {
    for (int fap = 3; fap <= kFapCount; ++fap)
      if (frame.has(fap)) held[static_cast<std::size_t>(fap - 1)] = frame.value(fap);
    if (frame.has(1)) viseme = frame.viseme, has_viseme = true;
    if (frame.has(2)) expression = frame.expression, has_expression = true;
    FapValues shown = held;
    add_scaled(shown, high_level_values(viseme, has_viseme, expression, has_expression), 1);
    shown[0] = shown[1] = 0;
    if (!numbers_.empty() && frame.number <= numbers_.back()) {
      shown_.back() = shown;  // numbers ascend; a repeated number replaces (defensive)
      continue;
    }
    numbers_.push_back(frame.number);
    shown_.push_back(shown);
  }
  frame_count_ = numbers_.empty() ? 0 : numbers_.back() + 1;
}

const FapValues& FaceTrack::at_frame(std::int64_t number) const {
  const auto after = std::upper_bound(numbers_.begin(), numbers_.end(), number);
  if (after == numbers_.begin()) return rest_;
  return shown_[static_cast<std::size_t>(after - numbers_.begin() - 1)];
}

const FapValues& FaceTrack::at_time(double seconds) const {
  // A small epsilon so that t = k / fps lands on frame k despite rounding.
  return at_frame(static_cast<std::int64_t>(std::floor(seconds * fps_ + 1e-6)));
}

std::vector<int> FaceTrack::moving_faps() const {
  std::vector<int> moving;
  for (int fap = 3; fap <= kFapCount; ++fap)
    for (const FapValues& v : shown_)
      if (v[static_cast<std::size_t>(fap - 1)] != 0) {
        moving.push_back(fap);
        break;
      }
  return moving;
}

}  // namespace fapc::face
