// FAP frames as plain values: what a .fap file holds, what the FBA encoder takes and what the
// decoder gives back. No I/O here.
#pragma once

#include <array>
#include <bitset>
#include <cstdint>
#include <string>
#include <vector>

#include "fapc/codec/fap_table.hpp"

namespace fapc {

struct VisemeFields {
  int select1 = 0;  // 0..14
  int select2 = 0;  // 0..14
  int blend = 0;    // 0..63
  int def = 0;      // 0/1
  friend bool operator==(const VisemeFields&, const VisemeFields&) = default;
};

struct ExpressionFields {
  int select1 = 0;     // 0..6
  int intensity1 = 0;  // 0..63
  int select2 = 0;     // 0..6
  int intensity2 = 0;  // 0..63
  int init_face = 0;   // 0/1
  int def = 0;         // 0/1
  friend bool operator==(const ExpressionFields&, const ExpressionFields&) = default;
};

// One frame: which FAPs it carries (the mask) and their values. FAPs outside the mask have no
// value in this frame; holding or interpolating them is the consumer's decision.
struct FapFrame {
  // Position on the sequence's frame grid: time = number / fps. Numbers ascend but may have gaps
  // (absent frames are absent, not zero).
  std::int64_t number = 0;
  std::bitset<kFapCount> mask;                   // bit i is FAP i+1
  std::array<std::int32_t, kFapCount> values{};  // index i is FAP i+1; only FAPs 3..68 are used
  VisemeFields viseme;                           // FAP 1, when masked
  ExpressionFields expression;                   // FAP 2, when masked

  bool has(int fap) const { return mask.test(static_cast<std::size_t>(fap - 1)); }
  std::int32_t value(int fap) const { return values[static_cast<std::size_t>(fap - 1)]; }
  void set(int fap, std::int32_t v) {
    mask.set(static_cast<std::size_t>(fap - 1));
    values[static_cast<std::size_t>(fap - 1)] = v;
  }
  // Equal masks, and equal values for every masked FAP (unmasked slots are ignored).
  bool same_content(const FapFrame& other) const;
};

struct FapSequence {
  std::string name;  // a label; writers use it as the header name
  int fps = 25;
  std::vector<FapFrame> frames;

  double duration_seconds() const;  // (last number + 1) / fps, 0 when empty
};

}  // namespace fapc
