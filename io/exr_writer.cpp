#include "io/exr_writer.hpp"

#include <libdeflate.h>

#include <algorithm>
#include <bit>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>

namespace silva::io {

namespace {

static_assert(std::endian::native == std::endian::little, "EXR files are little-endian; port put_* first");

constexpr int kLinesPerBlock = 16;     // ZIP_COMPRESSION
constexpr uint8_t kZipCompression = 3;
constexpr int32_t kPixelTypeFloat = 2;

struct Writer {
  std::vector<uint8_t> out;
  void bytes(const void* p, size_t n) {
    const auto* b = static_cast<const uint8_t*>(p);
    out.insert(out.end(), b, b + n);
  }
  void u8(uint8_t v) { bytes(&v, 1); }
  void i32(int32_t v) { bytes(&v, 4); }
  void f32(float v) { bytes(&v, 4); }
  void str(const char* s) { bytes(s, std::strlen(s) + 1); }
  void attribute(const char* name, const char* type, int32_t size) {
    str(name);
    str(type);
    i32(size);
  }
};

/// OpenEXR's ZIP pre-pass: split even/odd bytes into two halves, then byte deltas (+128).
void zip_predict(const uint8_t* raw, size_t n, uint8_t* out) {
  const size_t half = (n + 1) / 2;
  for (size_t i = 0; i < n; ++i) out[(i & 1) ? half + i / 2 : i / 2] = raw[i];
  for (size_t i = n - 1; i > 0; --i) out[i] = uint8_t(out[i] - out[i - 1] + 128);
}

struct FreeCompressor {
  void operator()(libdeflate_compressor* c) const { libdeflate_free_compressor(c); }
};

}  // namespace

std::vector<uint8_t> encode_exr_y(std::span<const float> values, int width, int height, int level) {
  if (width <= 0 || height <= 0 || values.size() != size_t(width) * size_t(height))
    throw std::invalid_argument("encode_exr_y: buffer of " + std::to_string(values.size()) +
                                " values does not match " + std::to_string(width) + "x" + std::to_string(height));
  if (level < 1 || level > 12) throw std::invalid_argument("EXR level must be 1..12, got " + std::to_string(level));
  std::unique_ptr<libdeflate_compressor, FreeCompressor> comp(libdeflate_alloc_compressor(level));
  if (!comp) throw std::bad_alloc();

  Writer w;
  w.i32(20000630);  // magic
  w.i32(2);         // version 2, single-part scanline, short names
  w.attribute("channels", "chlist", 19);
  w.str("Y");
  w.i32(kPixelTypeFloat);
  w.i32(0);  // pLinear + 3 reserved bytes
  w.i32(1);  // x sampling
  w.i32(1);  // y sampling
  w.str("");
  w.attribute("compression", "compression", 1);
  w.u8(kZipCompression);
  for (const char* window : {"dataWindow", "displayWindow"}) {
    w.attribute(window, "box2i", 16);
    w.i32(0);
    w.i32(0);
    w.i32(width - 1);
    w.i32(height - 1);
  }
  w.attribute("lineOrder", "lineOrder", 1);
  w.u8(0);  // INCREASING_Y
  w.attribute("pixelAspectRatio", "float", 4);
  w.f32(1.0f);
  w.attribute("screenWindowCenter", "v2f", 8);
  w.f32(0.0f);
  w.f32(0.0f);
  w.attribute("screenWindowWidth", "float", 4);
  w.f32(1.0f);
  w.str("");  // end of header

  const int blocks = (height + kLinesPerBlock - 1) / kLinesPerBlock;
  const size_t table_at = w.out.size();
  w.out.resize(table_at + 8 * size_t(blocks));
  const size_t row_bytes = size_t(width) * 4;
  std::vector<uint8_t> predicted(row_bytes * kLinesPerBlock);
  std::vector<uint8_t> packed(libdeflate_zlib_compress_bound(comp.get(), predicted.size()));
  for (int b = 0; b < blocks; ++b) {
    const uint64_t offset = w.out.size();
    std::memcpy(w.out.data() + table_at + 8 * size_t(b), &offset, 8);
    const int y0 = b * kLinesPerBlock;
    const size_t raw_size = row_bytes * size_t(std::min(kLinesPerBlock, height - y0));
    const auto* raw = reinterpret_cast<const uint8_t*>(values.data() + size_t(y0) * size_t(width));
    zip_predict(raw, raw_size, predicted.data());
    const size_t zsize = libdeflate_zlib_compress(comp.get(), predicted.data(), raw_size, packed.data(), packed.size());
    const bool stored = zsize == 0 || zsize >= raw_size;
    w.i32(y0);
    w.i32(int32_t(stored ? raw_size : zsize));
    w.bytes(stored ? raw : packed.data(), stored ? raw_size : zsize);
  }
  return std::move(w.out);
}

}  // namespace silva::io
