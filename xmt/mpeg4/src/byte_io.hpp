// Big-endian byte I/O for boxes and descriptors. The reader never reads past its end: a short
// read sets a sticky error (remembering the offset where it happened) and returns zeros, so a
// parser reads a whole structure and checks once (the habit of dav1d's bit reader).
#pragma once

#include <cstdint>
#include <string_view>

#include "fapc/mpeg4/fba_track.hpp"

namespace fapc::mpeg4 {

class ByteWriter {
 public:
  void u8(std::uint32_t v) { out_.push_back(static_cast<std::uint8_t>(v)); }
  void u16(std::uint32_t v) { put(v, 2); }
  void u24(std::uint32_t v) { put(v, 3); }
  void u32(std::uint32_t v) { put(v, 4); }
  void u64(std::uint64_t v) { put(v, 8); }
  void zeros(std::size_t n) { out_.insert(out_.end(), n, 0); }
  void bytes(const Bytes& b) { out_.insert(out_.end(), b.begin(), b.end()); }
  void fourcc(std::string_view code) {
    for (std::size_t i = 0; i < 4; ++i) u8(i < code.size() ? static_cast<std::uint8_t>(code[i]) : ' ');
  }
  // Overwrites 4 bytes at `at` (for sizes and offsets known only later).
  void patch_u32(std::size_t at, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) out_[at + static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(v >> (24 - 8 * i));
  }
  std::size_t size() const { return out_.size(); }
  const Bytes& data() const { return out_; }
  Bytes take() { return std::move(out_); }

 private:
  void put(std::uint64_t v, int n) {
    for (int i = n - 1; i >= 0; --i) out_.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
  }
  Bytes out_;
};

class ByteReader {
 public:
  // `base` is the offset of data[0] in the whole file, so errors can name file offsets.
  ByteReader(const std::uint8_t* data, std::size_t size, std::uint64_t base = 0)
      : data_(data), size_(size), base_(base) {}

  std::uint32_t u8() { return static_cast<std::uint32_t>(get(1)); }
  std::uint32_t u16() { return static_cast<std::uint32_t>(get(2)); }
  std::uint32_t u24() { return static_cast<std::uint32_t>(get(3)); }
  std::uint32_t u32() { return static_cast<std::uint32_t>(get(4)); }
  std::uint64_t u64() { return get(8); }
  Bytes bytes(std::size_t n) {
    if (!need(n)) return {};
    Bytes out(data_ + pos_, data_ + pos_ + n);
    pos_ += n;
    return out;
  }
  void skip(std::size_t n) {
    if (need(n)) pos_ += n;
  }

  bool failed() const { return failed_; }
  std::uint64_t failed_at() const { return base_ + failed_at_; }  // file offset of the short read
  std::size_t position() const { return pos_; }
  std::uint64_t offset() const { return base_ + pos_; }  // file offset of the next byte
  std::size_t remaining() const { return size_ - pos_; }
  const std::uint8_t* here() const { return data_ + pos_; }

 private:
  bool need(std::size_t n) {
    if (failed_) return false;
    if (n > size_ - pos_) {
      failed_ = true;
      failed_at_ = pos_;
      return false;
    }
    return true;
  }
  std::uint64_t get(std::size_t n) {
    if (!need(n)) return 0;
    std::uint64_t v = 0;
    for (std::size_t i = 0; i < n; ++i) v = (v << 8) | data_[pos_ + i];
    pos_ += n;
    return v;
  }
  const std::uint8_t* data_;
  std::size_t size_;
  std::uint64_t base_;
  std::size_t pos_ = 0;
  bool failed_ = false;
  std::size_t failed_at_ = 0;
};

}  // namespace fapc::mpeg4
