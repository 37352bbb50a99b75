// Writes bits most significant first into a growing byte buffer: the output side of the FBA
// bitstream (docs/fba-bitstream.md section 0.2). Bits gather in a 64-bit word and go out four bytes
// at a time. Private to fapcodec.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace fapc::fba {

class BitWriter {
 public:
  // The low `count` bits of `value`, most significant first; count is 0..32.
  void put_bits(std::uint32_t value, int count) {
    pending_ = (pending_ << count) | (value & ((std::uint64_t{1} << count) - 1));
    used_ += count;  // at most 31 + 32
    if (used_ >= 32) {
      used_ -= 32;
      const auto word = static_cast<std::uint32_t>(pending_ >> used_);
      // Four push_backs, not an insert of four: GCC 12 at -O3 reports a false overflow for the
      // insert into a vector it believes empty.
      for (int shift = 24; shift >= 0; shift -= 8) bytes_.push_back(static_cast<std::uint8_t>(word >> shift));
    }
  }
  void put_bit(int bit) { put_bits(static_cast<std::uint32_t>(bit & 1), 1); }

  // next_start_code(): a '0' then '1's up to the byte boundary, or a whole 0x7F when the position
  // is already aligned (section 5.9). Always 1 to 8 bits.
  void put_start_code_stuffing();

  std::size_t bit_count() const { return bytes_.size() * 8 + static_cast<std::size_t>(used_); }
  bool aligned() const { return used_ % 8 == 0; }
  // The bit at position `at` (0 = the first bit written); at < bit_count().
  int bit_at(std::size_t at) const;
  // How many of the last bits written are 0 (all of them, up to `limit`).
  std::size_t trailing_zero_bits(std::size_t limit) const;
  // Rewrites the bit at position `at` and inserts `count` (0..32) bits of `value` after it,
  // moving everything written after it. Rebuilds the tail bit by bit: for the rare plane that
  // must grow after it is written (plane_writer.cpp), not for the common path.
  void replace_bit_and_insert(std::size_t at, int bit, std::uint32_t value, int count);

  // The bytes written so far; a partial last byte is padded with zeros (callers align first).
  std::vector<std::uint8_t> take();

 private:
  // Moves the whole bytes of pending_ into bytes_, leaving fewer than 8 bits pending.
  void flush_whole_bytes();

  std::vector<std::uint8_t> bytes_;
  std::uint64_t pending_ = 0;  // its last `used_` bits (fewer than 32 between calls) are unwritten
  int used_ = 0;
};

}  // namespace fapc::fba
