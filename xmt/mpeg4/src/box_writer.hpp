// ISO base media boxes: a size, a four-character type, for full boxes a version and flags, then
// the payload. Boxes nest; sizes are patched in when a box is closed.
#pragma once

#include <string_view>
#include <vector>

#include "byte_io.hpp"

namespace fapc::mpeg4 {

class BoxWriter {
 public:
  void open(std::string_view type) {
    starts_.push_back(out_.size());
    out_.u32(0);
    out_.fourcc(type);
  }
  void open_full(std::string_view type, std::uint32_t version, std::uint32_t flags) {
    open(type);
    out_.u8(version);
    out_.u24(flags);
  }
  void close() {
    const std::size_t start = starts_.back();
    starts_.pop_back();
    out_.patch_u32(start, static_cast<std::uint32_t>(out_.size() - start));
  }
  ByteWriter& out() { return out_; }

 private:
  ByteWriter out_;
  std::vector<std::size_t> starts_;
};

}  // namespace fapc::mpeg4
