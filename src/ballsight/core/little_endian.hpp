#pragma once
// Explicit little-endian encoding of fixed-size fields, independent of the host's byte order and
// of struct padding: binary files are written and read field by field.

#include <bit>
#include <cassert>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace ballsight {

/// Appends little-endian fields to a byte string.
class LittleEndianWriter {
 public:
  explicit LittleEndianWriter(std::string& out) : out_(out) {}

  void u16(std::uint16_t v) { unsigned_bytes(v, 2); }
  void i16(std::int16_t v) { u16(static_cast<std::uint16_t>(v)); }
  void u32(std::uint32_t v) { unsigned_bytes(v, 4); }
  void u64(std::uint64_t v) { unsigned_bytes(v, 8); }
  void f32(float v) { u32(std::bit_cast<std::uint32_t>(v)); }
  void f64(double v) { u64(std::bit_cast<std::uint64_t>(v)); }
  /// Raw bytes, then zero padding up to `width` bytes (the text must fit).
  void padded(std::string_view text, std::size_t width) {
    assert(text.size() <= width);
    out_.append(text);
    out_.append(width - text.size(), '\0');
  }

 private:
  void unsigned_bytes(std::uint64_t v, int count) {
    for (int i = 0; i < count; ++i) out_.push_back(static_cast<char>((v >> (8 * i)) & 0xFFu));
  }
  std::string& out_;
};

/// Reads little-endian fields from a byte view; the caller checks the size first (reading past
/// the end is a programming error).
class LittleEndianReader {
 public:
  explicit LittleEndianReader(std::string_view bytes, std::size_t offset = 0)
      : bytes_(bytes), offset_(offset) {}

  std::size_t offset() const { return offset_; }
  std::uint16_t u16() { return static_cast<std::uint16_t>(unsigned_bytes(2)); }
  std::int16_t i16() { return static_cast<std::int16_t>(u16()); }
  std::uint32_t u32() { return static_cast<std::uint32_t>(unsigned_bytes(4)); }
  std::uint64_t u64() { return unsigned_bytes(8); }
  float f32() { return std::bit_cast<float>(u32()); }
  double f64() { return std::bit_cast<double>(u64()); }
  /// `width` raw bytes, cut at the first NUL.
  std::string padded(std::size_t width) {
    assert(offset_ + width <= bytes_.size());
    std::string_view field = bytes_.substr(offset_, width);
    offset_ += width;
    return std::string(field.substr(0, field.find('\0')));
  }

 private:
  std::uint64_t unsigned_bytes(int count) {
    assert(offset_ + static_cast<std::size_t>(count) <= bytes_.size());
    std::uint64_t v = 0;
    for (int i = 0; i < count; ++i) {
      v |= std::uint64_t{static_cast<unsigned char>(bytes_[offset_ + i])} << (8 * i);
    }
    offset_ += static_cast<std::size_t>(count);
    return v;
  }
  std::string_view bytes_;
  std::size_t offset_;
};

}  // namespace ballsight
