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

// Only masked slots carry anything: the rest at 0 (or default fields) need not be taped.
bool at_rest_outside_mask(const FapFrame& frame) {
  for (std::size_t i = 0; i < kFapCount; ++i)
    if (!frame.mask.test(i) && frame.values[i] != 0) return false;
  return (frame.has(1) || frame.viseme == VisemeFields{}) && (frame.has(2) || frame.expression == ExpressionFields{});
}

}  // namespace

void FrameTape::put(std::uint64_t v) {
  while (v >= 0x80) {
    bytes_.push_back(static_cast<std::uint8_t>(v | 0x80));
    v >>= 7;
  }
  bytes_.push_back(static_cast<std::uint8_t>(v));
}

bool FrameTape::record(const FapFrame& frame) {
  if (dropped_) return false;
  const bool every_slot = !at_rest_outside_mask(frame);
  const bool new_mask = frame.mask != previous_.mask;
  const bool jump = frame.number != previous_.number + 1;
  bytes_.push_back(static_cast<std::uint8_t>((new_mask ? kNewMask : 0) | (jump ? kNumberJump : 0) |
                                             (every_slot ? kEverySlot : 0)));
  if (new_mask)
    for (std::size_t byte = 0; byte < kMaskBytes; ++byte) {
      std::uint8_t bits = 0;
      for (std::size_t bit = 0; bit < 8 && byte * 8 + bit < kFapCount; ++bit)
        if (frame.mask.test(byte * 8 + bit)) bits = static_cast<std::uint8_t>(bits | (1u << bit));
      bytes_.push_back(bits);
    }
  if (jump) put_signed(frame.number - previous_.number);
  for (std::size_t i = 0; i < kFapCount; ++i)
    if (every_slot || frame.mask.test(i)) put_signed(std::int64_t{frame.values[i]} - previous_.values[i]);
  if (every_slot || frame.has(1)) {
    const auto now = fields(frame.viseme), before = fields(previous_.viseme);
    for (std::size_t f = 0; f < now.size(); ++f) put_signed(std::int64_t{now[f]} - before[f]);
  }
  if (every_slot || frame.has(2)) {
    const auto now = fields(frame.expression), before = fields(previous_.expression);
    for (std::size_t f = 0; f < now.size(); ++f) put_signed(std::int64_t{now[f]} - before[f]);
  }
  previous_ = frame;
  if (bytes_.size() > budget_) {
    dropped_ = true;
    std::vector<std::uint8_t>().swap(bytes_);  // `= {}` would keep the capacity
    return false;
  }
  return true;
}

FapFrame FrameTape::Player::next() {
  const std::vector<std::uint8_t>& bytes = tape_.bytes_;
  const auto get = [&] {
    std::uint64_t v = 0;
    for (int shift = 0;; shift += 7) {
      const std::uint8_t byte = bytes[at_++];
      v |= std::uint64_t{byte & 0x7Fu} << shift;
      if (byte < 0x80) return v;
    }
  };
  const auto get_signed = [&] {
    const std::uint64_t v = get();
    return static_cast<std::int64_t>(v >> 1) ^ -static_cast<std::int64_t>(v & 1);
  };
  const std::uint8_t flags = bytes[at_++];
  FapFrame frame;
  frame.mask = previous_.mask;
  if (flags & kNewMask) {
    frame.mask.reset();
    for (std::size_t byte = 0; byte < kMaskBytes; ++byte) {
      const std::uint8_t bits = bytes[at_++];
      for (std::size_t bit = 0; bit < 8 && byte * 8 + bit < kFapCount; ++bit)
        if (bits & (1u << bit)) frame.mask.set(byte * 8 + bit);
    }
  }
  frame.number = previous_.number + ((flags & kNumberJump) ? get_signed() : 1);
  const bool every_slot = flags & kEverySlot;
  for (std::size_t i = 0; i < kFapCount; ++i)
    if (every_slot || frame.mask.test(i))
      frame.values[i] = static_cast<std::int32_t>(previous_.values[i] + get_signed());
  // Each field as its difference from the previous frame's, in the order fields() lists them.
  const auto read = [&](const auto& before) {
    auto now = before;
    for (std::size_t f = 0; f < now.size(); ++f) now[f] = static_cast<int>(before[f] + get_signed());
    return now;
  };
  if (every_slot || frame.has(1)) {
    const auto v = read(fields(previous_.viseme));
    frame.viseme = VisemeFields{v[0], v[1], v[2], v[3]};
  }
  if (every_slot || frame.has(2)) {
    const auto e = read(fields(previous_.expression));
    frame.expression = ExpressionFields{e[0], e[1], e[2], e[3], e[4], e[5]};
  }
  previous_ = frame;
  return frame;
}

}  // namespace fapc::pipeline
