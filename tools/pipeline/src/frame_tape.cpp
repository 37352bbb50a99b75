#include "frame_tape.hpp"

#include <array>

namespace fapc::pipeline {

namespace {

// What a frame's first byte says follows.
enum : std::uint8_t {
  kNewMask = 1,     // the mask, 9 bytes, when it differs from the previous frame's
  kNumberJump = 2,  // the number's difference from the previous one, when it is not 1
  kEverySlot = 4,   // every value slot and field, when a slot outside the mask is not at rest
};

constexpr std::size_t kMaskBytes = (kFapCount + 7) / 8;

std::array<int, 4> fields(const VisemeFields& v) { return {v.select1, v.select2, v.blend, v.def}; }
std::array<int, 6> fields(const ExpressionFields& e) {
  return {e.select1, e.intensity1, e.select2, e.intensity2, e.init_face, e.def};
}

// Variable-length integers, 7 bits a byte, low bits first; signed ones zigzagged (small
// magnitudes of either sign take one byte). Most differences of a smooth animation take one.
std::uint8_t* put(std::uint8_t* out, std::uint64_t v) {
  for (; v >= 0x80; v >>= 7) *out++ = static_cast<std::uint8_t>(v | 0x80);
  *out++ = static_cast<std::uint8_t>(v);
  return out;
}
std::uint8_t* put_signed(std::uint8_t* out, std::int64_t v) {
  return put(out, (static_cast<std::uint64_t>(v) << 1) ^ static_cast<std::uint64_t>(v >> 63));
}
std::uint64_t get(const std::uint8_t*& in) {
  std::uint64_t v = *in++;
  if (v < 0x80) return v;
  v &= 0x7F;
  for (int shift = 7;; shift += 7) {
    const std::uint8_t byte = *in++;
    v |= std::uint64_t{byte & 0x7Fu} << shift;
    if (byte < 0x80) return v;
  }
}
std::int64_t get_signed(const std::uint8_t*& in) {
  const std::uint64_t v = get(in);
  return static_cast<std::int64_t>(v >> 1) ^ -static_cast<std::int64_t>(v & 1);
}

}  // namespace

void FrameTape::Slots::take(const std::bitset<kFapCount>& new_mask) {
  mask = new_mask;
  count = 0;
  for (std::size_t i = 0; i < kFapCount; ++i) {
    outside[i] = mask[i] ? 0 : -1;
    if (mask[i]) index[count++] = static_cast<std::uint8_t>(i);
  }
}

bool FrameTape::Slots::at_rest_outside(const FapFrame& frame) const {
  std::int32_t any = 0;  // a loop without a branch, over whole vectors
  for (std::size_t i = 0; i < kFapCount; ++i) any |= frame.values[i] & outside[i];
  return any == 0 && (frame.has(1) || frame.viseme == VisemeFields{}) &&
         (frame.has(2) || frame.expression == ExpressionFields{});
}

void FrameTape::drop() {
  dropped_ = true;
  bytes_ = 0;
  std::vector<Block>().swap(blocks_);
}

bool FrameTape::record(const FapFrame& frame) {
  if (dropped_) return false;
  // A new block when this frame might not fit the last: a frame is never split.
  if (blocks_.empty() || kBlockBytes - blocks_.back().size < kMostFrameBytes)
    blocks_.push_back(Block{std::make_unique<std::uint8_t[]>(kBlockBytes), 0});
  Block& block = blocks_.back();
  std::uint8_t* const start = block.bytes.get() + block.size;
  std::uint8_t* out = start;
  const bool new_mask = frame.mask != previous_.mask;
  if (new_mask) slots_.take(frame.mask);
  // Only masked slots carry anything: the rest at 0 (or default fields) need not be taped.
  const bool every_slot = !slots_.at_rest_outside(frame);
  const bool jump = frame.number != previous_.number + 1;
  *out++ =
      static_cast<std::uint8_t>((new_mask ? kNewMask : 0) | (jump ? kNumberJump : 0) | (every_slot ? kEverySlot : 0));
  if (new_mask)
    for (std::size_t byte = 0; byte < kMaskBytes; ++byte) {
      std::uint8_t bits = 0;
      for (std::size_t bit = 0; bit < 8 && byte * 8 + bit < kFapCount; ++bit)
        if (frame.mask[byte * 8 + bit]) bits = static_cast<std::uint8_t>(bits | (1u << bit));
      *out++ = bits;
    }
  if (jump) out = put_signed(out, frame.number - previous_.number);
  const auto put_slot = [&](std::size_t i) {
    out = put_signed(out, std::int64_t{frame.values[i]} - previous_.values[i]);
  };
  if (every_slot) {
    for (std::size_t i = 0; i < kFapCount; ++i) put_slot(i);
  } else {
    for (std::size_t k = 0; k < slots_.count; ++k) put_slot(slots_.index[k]);
  }
  if (every_slot || frame.has(1)) {
    const auto now = fields(frame.viseme), before = fields(previous_.viseme);
    for (std::size_t f = 0; f < now.size(); ++f) out = put_signed(out, std::int64_t{now[f]} - before[f]);
  }
  if (every_slot || frame.has(2)) {
    const auto now = fields(frame.expression), before = fields(previous_.expression);
    for (std::size_t f = 0; f < now.size(); ++f) out = put_signed(out, std::int64_t{now[f]} - before[f]);
  }
  previous_ = frame;
  const auto size = static_cast<std::size_t>(out - start);
  block.size += size;
  bytes_ += size;
  if (bytes_ > budget_) {
    drop();
    return false;
  }
  return true;
}

const FapFrame& FrameTape::Player::next() {
  // Past the end of a block: it is freed (unless kept) and the next one read.
  while (at_ == tape_.blocks_[block_].size) {
    if (!kept_) tape_.blocks_[block_].bytes.reset();
    ++block_;
    at_ = 0;
  }
  const std::uint8_t* const start = tape_.blocks_[block_].bytes.get() + at_;
  const std::uint8_t* in = start;
  const std::uint8_t flags = *in++;
  if (flags & kNewMask) {
    frame_.mask.reset();
    for (std::size_t byte = 0; byte < kMaskBytes; ++byte) {
      const std::uint8_t bits = *in++;
      for (std::size_t bit = 0; bit < 8 && byte * 8 + bit < kFapCount; ++bit)
        if (bits & (1u << bit)) frame_.mask.set(byte * 8 + bit);
    }
    slots_.take(frame_.mask);
  }
  frame_.number += (flags & kNumberJump) ? get_signed(in) : 1;
  // The frame is rebuilt in place over the previous one (which the recording took its differences
  // from): taped slots and fields move by their difference, the others are at rest.
  const bool every_slot = flags & kEverySlot;
  const auto get_slot = [&](std::size_t i) {
    frame_.values[i] = static_cast<std::int32_t>(frame_.values[i] + get_signed(in));
  };
  if (every_slot) {
    for (std::size_t i = 0; i < kFapCount; ++i) get_slot(i);
  } else {
    for (std::size_t i = 0; i < kFapCount; ++i) frame_.values[i] &= ~slots_.outside[i];
    for (std::size_t k = 0; k < slots_.count; ++k) get_slot(slots_.index[k]);
  }
  // Each field as its difference from the previous frame's, in the order fields() lists them.
  const auto read = [&](const auto& before) {
    auto now = before;
    for (std::size_t f = 0; f < now.size(); ++f) now[f] = static_cast<int>(before[f] + get_signed(in));
    return now;
  };
  if (every_slot || frame_.has(1)) {
    const auto v = read(fields(frame_.viseme));
    frame_.viseme = VisemeFields{v[0], v[1], v[2], v[3]};
  } else {
    frame_.viseme = VisemeFields{};
  }
  if (every_slot || frame_.has(2)) {
    const auto e = read(fields(frame_.expression));
    frame_.expression = ExpressionFields{e[0], e[1], e[2], e[3], e[4], e[5]};
  } else {
    frame_.expression = ExpressionFields{};
  }
  at_ += static_cast<std::size_t>(in - start);
  return frame_;
}

}  // namespace fapc::pipeline
