// MSB-first bit I/O for BIFS and the BIFS configuration. As with ByteReader, reading past the end
// is a sticky error that returns zeros; callers check failed() once per structure.
#pragma once

#include <cstdint>

#include "fapc/mpeg4/fba_track.hpp"

namespace fapc::mpeg4 {

class BitWriter {
 public:
  // Writes the low `bits` bits of `value`, most significant first (bits <= 32).
  void put(std::uint32_t value, int bits) {
    for (int i = bits - 1; i >= 0; --i) put_bit(((value >> i) & 1U) != 0);
  }
  void put_bit(bool bit) {
    if (used_ == 0) out_.push_back(0);
    if (bit) out_.back() = static_cast<std::uint8_t>(out_.back() | (0x80U >> used_));
    used_ = (used_ + 1) % 8;
  }
  // Pads with zero bits to the next byte boundary.
  Bytes finish() {
    used_ = 0;
    return std::move(out_);
  }
  std::uint64_t bit_count() const { return out_.size() * 8 - (used_ == 0 ? 0 : 8 - used_); }

 private:
  Bytes out_;
  int used_ = 0;  // bits used in the last byte (0: the last byte is full or there is none)
};

class BitReader {
 public:
  BitReader(const std::uint8_t* data, std::size_t size) : data_(data), size_bits_(size * 8) {}

  std::uint32_t get(int bits) {
    std::uint32_t v = 0;
    for (int i = 0; i < bits; ++i) v = (v << 1) | (get_bit() ? 1U : 0U);
    return v;
  }
  bool get_bit() {
    if (pos_ >= size_bits_) {
      failed_ = true;
      return false;
    }
    const bool bit = ((data_[pos_ / 8] >> (7 - pos_ % 8)) & 1U) != 0;
    ++pos_;
    return bit;
  }
  bool failed() const { return failed_; }
  std::uint64_t bit_position() const { return pos_; }
  std::uint64_t bits_left() const { return pos_ >= size_bits_ ? 0 : size_bits_ - pos_; }

 private:
  const std::uint8_t* data_;
  std::uint64_t size_bits_;
  std::uint64_t pos_ = 0;
  bool failed_ = false;
};

}  // namespace fapc::mpeg4
