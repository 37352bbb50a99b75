// Reads bits most significant first from a byte span: the input side of the FBA bitstream.
// Reading past the end yields zeros and moves the position on regardless, so a parser can read a
// whole syntax structure and check overrun() once at its end (the dav1d habit); the arithmetic
// decoder relies on this for its look-ahead, which may legitimately run past the last byte before
// it rewinds (docs/fba-bitstream.md section 6.6). Private to fapcodec.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>

namespace fapc::fba {

class BitReader {
 public:
  explicit BitReader(std::span<const std::uint8_t> data) : data_(data), size_bits_(data.size() * 8) {}

  int read_bit() {
    const std::size_t at = position_++;
    if (at >= size_bits_) return 0;
    return (data_[at >> 3] >> (7 - (at & 7))) & 1;
  }
  // count is 0..32.
  std::uint32_t read_bits(int count) {
    const std::uint32_t value = peek_bits(count);
    position_ += static_cast<std::size_t>(count);
    return value;
  }
  std::uint32_t peek_bits(int count) const { return peek_bits_at(position_, count); }
  // The same from any position, for a caller that keeps the position in a register meanwhile.
  std::uint32_t peek_bits_at(std::size_t position, int count) const {
    if (count == 0) return 0;
    // The 64 bits from the byte holding the next bit: at most 7 are already used, so 32 remain.
    const std::uint64_t window = load_window(position >> 3) << (position & 7);
    return static_cast<std::uint32_t>(window >> (64 - count));
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
  // Eight bytes from `byte` on, big-endian, zeros past the end.
  std::uint64_t load_window(std::size_t byte) const {
    std::uint64_t window = 0;
    if (byte + 8 <= data_.size()) {
      std::memcpy(&window, data_.data() + byte, sizeof window);
      return std::endian::native == std::endian::big ? window : __builtin_bswap64(window);
    }
    for (std::size_t i = 0; i < 8; ++i) window = (window << 8) | (byte + i < data_.size() ? data_[byte + i] : 0u);
    return window;
  }

  std::span<const std::uint8_t> data_;
  std::size_t size_bits_;
  std::size_t position_ = 0;
};

}  // namespace fapc::fba
