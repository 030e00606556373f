#pragma once
/// @file OMG CDR (XCDR1, little-endian) serialisation of ROS 2 messages: the 4-byte encapsulation
/// header, then each field aligned to its own size counted from the end of that header.
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace silva::io {

/// Builds one CDR_LE-encapsulated message in memory, field by field in the message's order.
class CdrWriter {
 public:
  /// An empty message holding only the encapsulation header (0x00 0x01 0x00 0x00).
  CdrWriter();
  /// Appends a uint8 (also bool and char).
  void u8(uint8_t v);
  /// Appends a uint16, aligned to 2.
  void u16(uint16_t v);
  /// Appends a uint32, aligned to 4.
  void u32(uint32_t v);
  /// Appends an int32, aligned to 4.
  void i32(int32_t v);
  /// Appends a float64, aligned to 8.
  void f64(double v);
  /// Appends a string: uint32 length counting the terminating NUL, the bytes, the NUL.
  void string(std::string_view s);
  /// Appends a uint8[] sequence: uint32 count, then the bytes.
  void bytes(std::span<const uint8_t> data);
  /// Reserves a uint8[] sequence of `count` bytes and returns where its bytes go (valid until the next append).
  uint8_t* reserve_bytes(size_t count);
  /// Appends a float64[] sequence (uint32 count, then the values) or, with `fixed`, a float64[N] array (no count).
  void f64_array(std::span<const double> values, bool fixed);
  /// The message so far.
  const std::vector<uint8_t>& data() const { return buf_; }
  /// Moves the message out; the writer is then empty (not even a header).
  std::vector<uint8_t> take() { return std::move(buf_); }

 private:
  void align(size_t n);
  template <class T>
  void put(T v);
  std::vector<uint8_t> buf_;
};

}  // namespace silva::io
