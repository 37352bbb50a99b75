#include "fba/bit_writer.hpp"

#include <utility>

namespace fapc::fba {

void BitWriter::put_start_code_stuffing() {
  // Starting aligned, this writes 0 and seven 1s: the 0x7F the standard asks for.
  put_bit(0);
  while (!aligned()) put_bit(1);
}

std::vector<std::uint8_t> BitWriter::take() {
  if (used_ > 0) {
    bytes_.push_back(static_cast<std::uint8_t>(current_ << (8 - used_)));
    current_ = 0;
    used_ = 0;
  }
  return std::exchange(bytes_, {});
}

}  // namespace fapc::fba
