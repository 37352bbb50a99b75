// Checks of what other decoders need from a stream, written from docs/fba-bitstream.md
// (sections 5.3, 5.9, 6.4 to 6.6, 12.6) and not from fapc's writer: they look at the bytes.
//   * zeros_before_start_codes: how many zero bits come right before each start code after the
//     object start code. The reference decoder decodes a segment with 16 bits of look-ahead and
//     rewinds a fixed 14; a one-bit stuffing '0' lets a segment's trailing zeros run into the 23
//     zeros of the next start code, and a run past 22 in its look-ahead is a "stuffing error".
//   * reference_drops_last_plane: after each plane the reference decoder skips to the next byte
//     boundary (a whole byte when already aligned) and stops if the 32 bits there are the end
//     code. A last plane that ends before that boundary is never decoded.
//   * field_shown_as_is: a blend or intensity as every decoder shows it: inside 0..63 and a
//     multiple of fap_quant (fapc's decoder clamps a reconstruction of 64 to 63, which is not).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "fapc/codec/fba.hpp"

namespace fapc::test {

inline int bit_of(const std::vector<std::uint8_t>& bytes, std::size_t at) {
  return (bytes[at / 8] >> (7 - at % 8)) & 1;
}

// For every byte-aligned 00 00 01 after the first four bytes, the number of zero bits before it.
inline std::vector<std::size_t> zeros_before_start_codes(const std::vector<std::uint8_t>& bytes) {
  std::vector<std::size_t> runs;
  for (std::size_t i = 4; i + 2 < bytes.size(); ++i) {
    if (bytes[i] != 0 || bytes[i + 1] != 0 || bytes[i + 2] != 1) continue;
    std::size_t zeros = 0;
    while (zeros < 8 * i && bit_of(bytes, 8 * i - 1 - zeros) == 0) ++zeros;
    runs.push_back(zeros);
  }
  return runs;
}

inline std::size_t longest_zero_run_before_a_start_code(const std::vector<std::uint8_t>& bytes) {
  std::size_t longest = 0;
  for (const std::size_t run : zeros_before_start_codes(bytes)) longest = run > longest ? run : longest;
  return longest;
}

// `last_plane_start`: the bit where the last plane starts (where the plane before it ended).
inline bool reference_drops_last_plane(const std::vector<std::uint8_t>& bytes, std::size_t last_plane_start) {
  const std::size_t boundary = last_plane_start / 8 + 1;  // in bytes; a whole byte on when aligned
  return boundary + 4 <= bytes.size() && bytes[boundary] == 0x00 && bytes[boundary + 1] == 0x00 &&
         bytes[boundary + 2] == 0x01 && bytes[boundary + 3] == 0xB1;
}

inline bool field_shown_as_is(int value, int quant) {
  return value >= 0 && value <= 63 && (quant == 0 || value % quant == 0);
}

// The skip_frames part of a plane's temporal header (docs/fba-bitstream.md section 5.3), read from
// the bytes: where the flag is and the 4-bit chunks after it. `aligned`: the plane opens with its
// start code.
struct SkipField {
  std::size_t flag_at = 0;
  int flag = 0;
  std::vector<int> chunks;
};

inline SkipField read_skip_field(const std::vector<std::uint8_t>& bytes, std::size_t plane_start, bool aligned) {
  std::size_t at = plane_start + (aligned ? 32 : 0);
  const auto read = [&](int count) {
    int v = 0;
    for (int i = 0; i < count; ++i) v = v << 1 | bit_of(bytes, at++);
    return v;
  };
  const int intra = read(1);
  read(2);  // fba_object_mask
  if (intra) {
    if (read(1)) read(13);  // is_frame_rate: frame_rate, seconds, frequency_offset
    if (read(1)) read(18);  // is_time_code
  }
  SkipField skip;
  skip.flag_at = at;
  skip.flag = read(1);
  if (skip.flag) {
    int chunk = 0;
    do {
      chunk = read(4);
      skip.chunks.push_back(chunk);
    } while (chunk == 15);
  }
  return skip;
}

}  // namespace fapc::test
