// Private: a vector in blocks of 2^16 elements, for the Mimic compiler's per-action tables.
// It never copies what it holds as it grows (a doubling vector of a million leaves copies them
// and briefly holds both blocks), its blocks are big enough for the allocator to give them their
// own pages (a std::deque's 512-byte blocks sit among the schedule tree's nodes and keep the
// tree's freed memory from going back to the system), and the blocks before an index can be let
// go while the rest is read.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

namespace fapc::mimic {

template <class T>
class ChunkedVector {
 public:
  static constexpr std::size_t kShift = 16;
  static constexpr std::size_t kChunk = std::size_t{1} << kShift;

  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }

  T& operator[](std::size_t i) { return chunks_[i >> kShift][i & (kChunk - 1)]; }
  const T& operator[](std::size_t i) const { return chunks_[i >> kShift][i & (kChunk - 1)]; }

  void push_back(const T& value) {
    if (size_ == chunks_.size() * kChunk) chunks_.push_back(std::make_unique<T[]>(kChunk));
    (*this)[size_++] = value;
  }

  // Drops the elements from `size` on (their blocks are kept for what follows).
  void truncate(std::size_t size) {
    if (size < size_) size_ = size;
  }

  // Lets go of the blocks wholly before element `i`; reading them afterwards is an error.
  void release_before(std::size_t i) {
    for (; released_ < chunks_.size() && (released_ + 1) * kChunk <= i; ++released_) chunks_[released_].reset();
  }

 private:
  std::vector<std::unique_ptr<T[]>> chunks_;
  std::size_t size_ = 0;
  std::size_t released_ = 0;  // chunks_[0, released_) are let go
};

}  // namespace fapc::mimic
