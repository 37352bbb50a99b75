// Reads bits most significant first from a byte span: the input side of the FBA bitstream.
// Reading past the end yields zeros and moves the position on regardless, so a parser can read a
// whole syntax structure and check overrun() once at its end (the dav1d habit); the arithmetic
// decoder relies on this for its look-ahead, which may legitimately run past the last byte before
// it rewinds (fba-bitstream.md section 6.6). Private to fapcodec.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

namespace fapc::fba {

class BitReader {
 public:
  explicit BitReader(std::span<const std::uint8_t> data)
      : data_(data), size_bits_(data.size() * 8) {}

  int read_bit() {
    const std::size_t at = position_++;
    if (at >= size_bits_) return 0;
    return (data_[at >> 3] >> (7 - (at & 7))) & 1;
  }
  // count is 0..32.
  std::uint32_t read_bits(int count) {
    std::uint32_t value = 0;
    for (int i = 0; i < count; ++i) value = (value << 1) | static_cast<std::uint32_t>(read_bit());
    return value;
  }
  std::uint32_t peek_bits(int count) const {
    BitReader copy = *this;
    return copy.read_bits(count);
  }

  std::size_t position() const { return position_; }  // in bits from the start
  void seek(std::size_t bit_position) { position_ = bit_position; }
  std::size_t size_bits() const { return size_bits_; }
  bool overrun() const { return position_ > size_bits_; }
  bool at_end() const { return position_ >= size_bits_; }
  bool aligned() const { return (position_ & 7) == 0; }
  std::size_t bits_to_boundary() const { return (8 - (position_ & 7)) & 7; }
  // The byte that holds the next bit, for diagnostics.
  std::int64_t byte_offset() const { return static_cast<std::int64_t>(position_ / 8); }

 private:
  std::span<const std::uint8_t> data_;
  std::size_t size_bits_;
  std::size_t position_ = 0;
};

}  // namespace fapc::fba
