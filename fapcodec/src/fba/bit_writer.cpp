#include "fba/bit_writer.hpp"

#include <utility>

namespace fapc::fba {

void BitWriter::put_start_code_stuffing() {
  // Starting aligned, this writes 0 and seven 1s: the 0x7F the standard asks for.
  const int ones = 7 - used_ % 8;
  put_bits(0, 1);
  put_bits((1u << ones) - 1, ones);
}

std::vector<std::uint8_t> BitWriter::take() {
  for (; used_ >= 8; used_ -= 8) bytes_.push_back(static_cast<std::uint8_t>(pending_ >> (used_ - 8)));
  if (used_ > 0) bytes_.push_back(static_cast<std::uint8_t>(pending_ << (8 - used_)));
  pending_ = 0;
  used_ = 0;
  return std::exchange(bytes_, {});
}

}  // namespace fapc::fba
