// Walking ISO base media boxes inside a byte range. A box that claims more bytes than its parent
// has left, or fewer than its own header, is an error naming its offset.
#pragma once

#include <string>
#include <vector>

#include "byte_io.hpp"
#include "fapc/codec/diagnostic.hpp"
#include "fapc/mpeg4/codes.hpp"

namespace fapc::mpeg4 {

struct Box {
  std::string type;             // four characters; bytes outside printable ASCII shown as '?'
  std::uint64_t offset = 0;     // file offset of the box's first byte
  ByteReader body{nullptr, 0};  // the payload after the header
};

// The boxes one after another in `range` (whose file offset is range.offset()).
Result<std::vector<Box>> read_boxes(ByteReader range, const std::string& file);

inline Diagnostic box_error(ErrorCode code, const std::string& file, std::uint64_t offset, const std::string& message) {
  return make_error(code, Location::binary(file, static_cast<std::int64_t>(offset)), message);
}

}  // namespace fapc::mpeg4
