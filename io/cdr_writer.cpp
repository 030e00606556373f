#include "io/cdr_writer.hpp"

#include <bit>
#include <cstring>

namespace silva::io {

namespace {
/// Bytes of the encapsulation header; alignment counts from its end.
constexpr size_t kHeaderBytes = 4;
static_assert(std::endian::native == std::endian::little, "CDR_LE values are copied as the host stores them");
}  // namespace

CdrWriter::CdrWriter() : buf_{0x00, 0x01, 0x00, 0x00} {}

void CdrWriter::align(size_t n) {
  const size_t offset = buf_.size() - kHeaderBytes;
  buf_.resize(buf_.size() + (n - offset % n) % n, 0);
}

template <class T>
void CdrWriter::put(T v) {
  align(sizeof(T));
  const size_t at = buf_.size();
  buf_.resize(at + sizeof(T));
  std::memcpy(buf_.data() + at, &v, sizeof(T));
}

void CdrWriter::u8(uint8_t v) { buf_.push_back(v); }
void CdrWriter::u16(uint16_t v) { put(v); }
void CdrWriter::u32(uint32_t v) { put(v); }
void CdrWriter::i32(int32_t v) { put(v); }
void CdrWriter::f64(double v) { put(v); }

void CdrWriter::string(std::string_view s) {
  u32(uint32_t(s.size() + 1));
  buf_.insert(buf_.end(), s.begin(), s.end());
  buf_.push_back(0);
}

uint8_t* CdrWriter::reserve_bytes(size_t count) {
  u32(uint32_t(count));
  const size_t at = buf_.size();
  buf_.resize(at + count);
  return buf_.data() + at;
}

void CdrWriter::bytes(std::span<const uint8_t> data) {
  uint8_t* out = reserve_bytes(data.size());
  if (!data.empty()) std::memcpy(out, data.data(), data.size());
}

void CdrWriter::f64_array(std::span<const double> values, bool fixed) {
  if (!fixed) u32(uint32_t(values.size()));
  for (const double v : values) f64(v);
}

}  // namespace silva::io
