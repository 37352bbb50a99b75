// The encoder's window of frames, packed: a group of planes runs from one intra plane to the next,
// and where no mask changes (no --intra-period) that is the whole sequence, a million frames
// say, which as FapFrames cost 336 bytes each. Here a frame costs 16 bytes and 4 per masked FAP
// (and 40 when it carries FAP 1 or 2): a group of a million frames of five FAPs, 36 MB.
// Indexing gives a light view that reads like the FapFrame pushed (number, mask, value(fap),
// has(fap), viseme, expression), for the masked FAPs; unmasked FAPs read 0, which nothing of the
// encoder reads. Private to fapcodec.
#pragma once

#include <array>
#include <bitset>
#include <cstdint>
#include <vector>

#include "fapc/codec/fap_sequence.hpp"

namespace fapc::fba {

class FrameWindow {
  struct Mask {
    std::bitset<kFapCount> bits;
    std::array<std::uint8_t, kFapCount> slot{};  // where FAP i+1 sits among a frame's values
    std::uint32_t values = 0;                    // masked FAPs 3..68
  };

 public:
  // Frame k of the window, as pushed (masked FAPs only).
  class View {
   public:
    std::int64_t number;
    const std::bitset<kFapCount>& mask;
    VisemeFields viseme;
    ExpressionFields expression;

    bool has(int fap) const { return mask.test(static_cast<std::size_t>(fap - 1)); }
    std::int32_t value(int fap) const {
      return has(fap) ? values_[layout_.slot[static_cast<std::size_t>(fap - 1)]] : 0;
    }

   private:
    friend class FrameWindow;
    View(std::int64_t n, const Mask& layout, const std::int32_t* values);
    const Mask& layout_;
    const std::int32_t* values_;
  };

  std::size_t size() const { return frames_.size(); }
  bool empty() const { return frames_.empty(); }
  View operator[](std::size_t k) const {
    const Entry& e = frames_[k];
    return View(e.number, masks_[e.mask], pool_.data() + e.first);
  }
  // Frame k's values of its masked FAPs 3..68, in ascending FAP order: within a group (one mask)
  // the j-th is that of the group's j-th FAP. For the planner's loops over every value, which
  // need no view per value.
  const std::int32_t* masked_values(std::size_t k) const { return pool_.data() + frames_[k].first; }
  void push_back(const FapFrame& frame);
  // Drops the first n frames (a group written).
  void erase_front(std::size_t n);

 private:
  struct Entry {
    std::int64_t number;
    std::uint32_t mask;   // into masks_
    std::uint32_t first;  // into pool_: the masked values, then FAP 1's 4 and FAP 2's 6 fields
  };
  std::vector<Entry> frames_;
  std::vector<Mask> masks_;  // the window's distinct masks, in order of first use
  std::vector<std::int32_t> pool_;
};

}  // namespace fapc::fba
