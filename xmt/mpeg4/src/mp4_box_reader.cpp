#include "mp4_box_reader.hpp"

namespace fapc::mpeg4 {

Result<std::vector<Box>> read_boxes(ByteReader range, const std::string& file) {
  std::vector<Box> boxes;
  while (range.remaining() > 0) {
    Box box;
    box.offset = range.offset();
    const std::size_t left = range.remaining();
    if (left < 8)
      return box_error(codes::mp4::bad_box, file, box.offset,
                       std::to_string(left) + " stray byte(s) where a box header (8 bytes) should be");
    std::uint64_t size = range.u32();
    for (int i = 0; i < 4; ++i) {
      const auto c = static_cast<char>(range.u8());
      box.type += (c >= 0x20 && c < 0x7F) ? c : '?';
    }
    std::uint64_t header = 8;
    if (size == 1) {
      if (range.remaining() < 8)
        return box_error(codes::mp4::box_truncated, file, box.offset,
                         "box '" + box.type + "' cut short in its 64-bit size");
      size = range.u64();
      header = 16;
    } else if (size == 0) {
      size = left;  // extends to the end of its parent
    }
    if (size < header)
      return box_error(codes::mp4::bad_box, file, box.offset,
                       "box '" + box.type + "' claims " + std::to_string(size) + " bytes, less than its own header");
    if (size > left)
      return box_error(codes::mp4::bad_box, file, box.offset,
                       "box '" + box.type + "' claims " + std::to_string(size) + " bytes but only " +
                           std::to_string(left) + " are left in its parent");
    const auto payload = static_cast<std::size_t>(size - header);
    box.body = ByteReader(range.here(), payload, range.offset());
    range.skip(payload);
    boxes.push_back(std::move(box));
  }
  return boxes;
}

}  // namespace fapc::mpeg4
