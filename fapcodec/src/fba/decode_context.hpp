// What every part of the decoder shares: the bit reader, the arithmetic decoder reading from it,
// and the file name, with the checks that turn a bad position into a Diagnostic with its byte
// offset. Private to fapcodec.
#pragma once

#include <span>
#include <string>

#include "fapc/codec/codes.hpp"
#include "fapc/codec/diagnostic.hpp"
#include "fba/arith_decoder.hpp"
#include "fba/bit_reader.hpp"

namespace fapc::fba {

struct DecodeContext {
  DecodeContext(std::span<const std::uint8_t> bytes, std::string file_name) : in(bytes), file(std::move(file_name)) {}
  DecodeContext(const DecodeContext&) = delete;
  DecodeContext& operator=(const DecodeContext&) = delete;

  BitReader in;
  ArithDecoder coder{in};
  std::string file;

  Diagnostic error_at(ErrorCode code, std::int64_t byte, const std::string& message) const {
    return make_error(code, Location::binary(file, byte), message);
  }
  Diagnostic error_here(ErrorCode code, const std::string& message) const {
    return error_at(code, in.byte_offset(), message);
  }
  // The stream ends before its syntax does: a kind callers (and StreamReader::explain) decide by.
  Diagnostic truncated_at(std::int64_t byte, const std::string& message) const {
    return make_error(codes::fba::truncated, Location::binary(file, byte), message);
  }

  // After reading a structure: did it run past the last byte?
  Status check_inside(const std::string& what) const {
    if (!in.overrun()) return ok_status();
    return truncated_at(static_cast<std::int64_t>(in.size_bits() / 8), "stream ends inside " + what + " (truncated?)");
  }
  // A marker bit that must be 1 (docs/fba-bitstream.md section 5.9).
  Status read_marker(const char* where) {
    const std::int64_t byte = in.byte_offset();
    if (in.read_bit() == 1) return ok_status();
    return error_at(codes::fba::marker_bit, byte, std::string("marker bit ") + where + " is 0 (corrupt stream?)");
  }
  // Ends an arithmetic-coded segment (section 6.6).
  Status finish_segment(const char* what) {
    if (!coder.finish())
      return error_at(codes::fba::start_code_in_segment, static_cast<std::int64_t>(coder.bad_bit_position() / 8),
                      std::string("23 zero bits in a row inside the ") + what +
                          " segment: a start code cannot appear there (corrupt stream?)");
    return check_inside(std::string("the ") + what + " segment");
  }
};

}  // namespace fapc::fba
