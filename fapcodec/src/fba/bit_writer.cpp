#include "fba/bit_writer.hpp"

#include <utility>

namespace fapc::fba {

void BitWriter::put_start_code_stuffing() {
  // Starting aligned, this writes 0 and seven 1s: the 0x7F the standard asks for.
  const int ones = 7 - used_ % 8;
  put_bits(0, 1);
  put_bits((1u << ones) - 1, ones);
}

int BitWriter::bit_at(std::size_t at) const {
  const std::size_t flushed = bytes_.size() * 8;
  if (at < flushed) return (bytes_[at / 8] >> (7 - at % 8)) & 1;
  return static_cast<int>((pending_ >> (static_cast<std::size_t>(used_) - 1 - (at - flushed))) & 1);
}

std::size_t BitWriter::trailing_zero_bits(std::size_t limit) const {
  const std::size_t end = bit_count();
  std::size_t zeros = 0;
  while (zeros < limit && zeros < end && bit_at(end - 1 - zeros) == 0) ++zeros;
  return zeros;
}

void BitWriter::flush_whole_bytes() {
  for (; used_ >= 8; used_ -= 8) bytes_.push_back(static_cast<std::uint8_t>(pending_ >> (used_ - 8)));
  pending_ &= (std::uint64_t{1} << used_) - 1;
}

void BitWriter::replace_bit_and_insert(std::size_t at, int bit, std::uint32_t value, int count) {
  std::vector<std::uint8_t> tail;  // one bit per entry, those after `at`
  for (std::size_t i = at + 1; i < bit_count(); ++i) tail.push_back(static_cast<std::uint8_t>(bit_at(i)));
  // Cut the stream back to its first `at` bits.
  flush_whole_bytes();
  const std::size_t flushed = bytes_.size() * 8;
  if (at >= flushed) {
    pending_ >>= flushed + static_cast<std::size_t>(used_) - at;
    used_ = static_cast<int>(at - flushed);
  } else {
    const int keep = static_cast<int>(at % 8);
    pending_ = static_cast<std::uint64_t>(bytes_[at / 8] >> (8 - keep));
    used_ = keep;
    bytes_.resize(at / 8);
  }
  put_bit(bit);
  put_bits(value, count);
  for (const std::uint8_t b : tail) put_bit(b);
}

std::vector<std::uint8_t> BitWriter::take() {
  for (; used_ >= 8; used_ -= 8) bytes_.push_back(static_cast<std::uint8_t>(pending_ >> (used_ - 8)));
  if (used_ > 0) bytes_.push_back(static_cast<std::uint8_t>(pending_ << (8 - used_)));
  pending_ = 0;
  used_ = 0;
  return std::exchange(bytes_, {});
}

}  // namespace fapc::fba
