#include "fba/frame_window.hpp"

namespace fapc::fba {

namespace {

constexpr std::size_t kFirstValueSlot = 2;  // FAPs 1 and 2 carry fields, not values

}  // namespace

FrameWindow::View::View(std::int64_t n, const Mask& layout, const std::int32_t* values)
    : number(n), mask(layout.bits), viseme{}, expression{}, layout_(layout), values_(values) {
  const std::int32_t* fields = values + layout.values;
  if (has(1)) {
    viseme = VisemeFields{fields[0], fields[1], fields[2], fields[3]};
    fields += 4;
  }
  if (has(2)) expression = ExpressionFields{fields[0], fields[1], fields[2], fields[3], fields[4], fields[5]};
}

void FrameWindow::push_back(const FapFrame& frame) {
  if (masks_.empty() || masks_.back().bits != frame.mask) {
    Mask& m = masks_.emplace_back();
    m.bits = frame.mask;
    for (std::size_t i = kFirstValueSlot; i < kFapCount; ++i)
      if (frame.mask.test(i)) m.slot[i] = static_cast<std::uint8_t>(m.values++);
  }
  frames_.push_back(
      Entry{frame.number, static_cast<std::uint32_t>(masks_.size() - 1), static_cast<std::uint32_t>(pool_.size())});
  for (std::size_t i = kFirstValueSlot; i < kFapCount; ++i)
    if (frame.mask.test(i)) pool_.push_back(frame.values[i]);
  if (frame.has(1)) {
    const VisemeFields& v = frame.viseme;
    pool_.insert(pool_.end(), {v.select1, v.select2, v.blend, v.def});
  }
  if (frame.has(2)) {
    const ExpressionFields& e = frame.expression;
    pool_.insert(pool_.end(), {e.select1, e.intensity1, e.select2, e.intensity2, e.init_face, e.def});
  }
}

void FrameWindow::erase_front(std::size_t n) {
  if (n >= frames_.size()) {
    frames_.clear();
    masks_.clear();
    pool_.clear();
    return;
  }
  // What stays is a frame or two (the group's successor): move it down.
  const std::uint32_t first_value = frames_[n].first;
  const std::uint32_t first_mask = frames_[n].mask;
  frames_.erase(frames_.begin(), frames_.begin() + static_cast<std::ptrdiff_t>(n));
  pool_.erase(pool_.begin(), pool_.begin() + first_value);
  masks_.erase(masks_.begin(), masks_.begin() + first_mask);
  for (Entry& e : frames_) {
    e.first -= first_value;
    e.mask -= first_mask;
  }
}

}  // namespace fapc::fba
