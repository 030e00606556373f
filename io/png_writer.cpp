#include "io/png_writer.hpp"

#include <libdeflate.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <memory>
#include <new>
#include <stdexcept>
#include <string>

namespace silva::io {

namespace {

constexpr uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
constexpr size_t kMaxChunk = size_t(1) << 30;  // PNG allows 2^31 - 1 bytes per chunk.

/// Per-thread libdeflate compressors, one per level (compressors are not thread-safe).
libdeflate_compressor* compressor_for(int level) {
  struct Free {
    void operator()(libdeflate_compressor* c) const { libdeflate_free_compressor(c); }
  };
  thread_local std::unique_ptr<libdeflate_compressor, Free> cache[13];
  auto& slot = cache[level];
  if (!slot) slot.reset(libdeflate_alloc_compressor(level));
  if (!slot) throw std::bad_alloc();
  return slot.get();
}

void put_u32(uint8_t* p, uint32_t v) {
  p[0] = uint8_t(v >> 24);
  p[1] = uint8_t(v >> 16);
  p[2] = uint8_t(v >> 8);
  p[3] = uint8_t(v);
}

/// Appends one chunk (length, type, data, CRC) to `out`.
void append_chunk(std::vector<uint8_t>& out, const char type[4], const uint8_t* data, size_t size) {
  const size_t at = out.size();
  out.resize(at + 8);
  put_u32(out.data() + at, uint32_t(size));
  std::memcpy(out.data() + at + 4, type, 4);
  out.insert(out.end(), data, data + size);
  uint8_t crc[4];
  put_u32(crc, libdeflate_crc32(0, out.data() + at + 4, size + 4));
  out.insert(out.end(), crc, crc + 4);
}

/// A per-thread byte buffer of at least `size` bytes, reused across calls (grown, never cleared).
uint8_t* scratch(std::vector<uint8_t>& buffer, size_t size) {
  if (buffer.size() < size) buffer.resize(size);
  return buffer.data();
}

uint8_t paeth(uint8_t a, uint8_t b, uint8_t c) {
  const int p = int(a) + int(b) - int(c);
  const int pa = std::abs(p - int(a)), pb = std::abs(p - int(b)), pc = std::abs(p - int(c));
  if (pa <= pb && pa <= pc) return a;
  return pb <= pc ? b : c;
}

/// Filters one row of `n` bytes with `bpp` bytes per pixel into `out` (n bytes, after the type).
void filter_row(PngFilter f, const uint8_t* row, const uint8_t* prev, size_t n, size_t bpp, uint8_t* out) {
  switch (f) {
    case PngFilter::None:
      for (size_t i = 0; i < n; ++i) out[i] = row[i];
      break;
    case PngFilter::Sub:
      for (size_t i = 0; i < bpp; ++i) out[i] = row[i];
      for (size_t i = bpp; i < n; ++i) out[i] = uint8_t(row[i] - row[i - bpp]);
      break;
    case PngFilter::Up:
      for (size_t i = 0; i < n; ++i) out[i] = uint8_t(row[i] - (prev ? prev[i] : 0));
      break;
    case PngFilter::Average:
      for (size_t i = 0; i < n; ++i) {
        const int a = i >= bpp ? row[i - bpp] : 0, b = prev ? prev[i] : 0;
        out[i] = uint8_t(row[i] - ((a + b) >> 1));
      }
      break;
    case PngFilter::Paeth:
      for (size_t i = 0; i < n; ++i) {
        const uint8_t a = i >= bpp ? row[i - bpp] : 0, b = prev ? prev[i] : 0;
        const uint8_t c = (i >= bpp && prev) ? prev[i - bpp] : 0;
        out[i] = uint8_t(row[i] - paeth(a, b, c));
      }
      break;
  }
}

/// Encodes rows of raw big-endian sample bytes (`bpp` bytes per pixel) as a PNG.
std::vector<uint8_t> encode(const uint8_t* raw, int width, int height, size_t bpp, uint8_t bit_depth,
                            uint8_t color_type, PngOptions options) {
  if (options.level < 0 || options.level > 12)
    throw std::invalid_argument("PNG level must be 0..12, got " + std::to_string(options.level));
  const size_t row_bytes = size_t(width) * bpp;
  // The filtered rows and the zlib stream live in per-thread scratch: a frame's PNGs are
  // several megabytes each, and fresh zero-filled buffers per file cost a page fault per 4 KiB.
  thread_local std::vector<uint8_t> filtered_scratch, zlib_scratch;
  const size_t filtered_size = size_t(height) * (row_bytes + 1);
  uint8_t* filtered = scratch(filtered_scratch, filtered_size);
  for (int y = 0; y < height; ++y) {
    uint8_t* dst = filtered + size_t(y) * (row_bytes + 1);
    const uint8_t* row = raw + size_t(y) * row_bytes;
    dst[0] = uint8_t(options.filter);
    filter_row(options.filter, row, y > 0 ? row - row_bytes : nullptr, row_bytes, bpp, dst + 1);
  }
  libdeflate_compressor* c = compressor_for(options.level);
  const size_t bound = libdeflate_zlib_compress_bound(c, filtered_size);
  uint8_t* zlib = scratch(zlib_scratch, bound);
  const size_t zsize = libdeflate_zlib_compress(c, filtered, filtered_size, zlib, bound);
  if (zsize == 0) throw std::logic_error("libdeflate_zlib_compress: bound too small");

  const size_t idat_chunks = (zsize + kMaxChunk - 1) / kMaxChunk;
  uint8_t ihdr[13] = {};
  put_u32(ihdr, uint32_t(width));
  put_u32(ihdr + 4, uint32_t(height));
  ihdr[8] = bit_depth;
  ihdr[9] = color_type;  // compression, filter method and interlace stay 0
  std::vector<uint8_t> out(std::begin(kSignature), std::end(kSignature));
  out.reserve(sizeof kSignature + (12 + sizeof ihdr) + 12 * idat_chunks + zsize + 12);
  append_chunk(out, "IHDR", ihdr, sizeof ihdr);
  for (size_t at = 0; at < zsize; at += kMaxChunk) append_chunk(out, "IDAT", zlib + at, std::min(kMaxChunk, zsize - at));
  append_chunk(out, "IEND", nullptr, 0);
  return out;
}

void check_size(size_t got, int width, int height, size_t per_pixel, const char* what) {
  if (width <= 0 || height <= 0 || got != size_t(width) * size_t(height) * per_pixel)
    throw std::invalid_argument(std::string(what) + ": buffer of " + std::to_string(got) +
                                " values does not match " + std::to_string(width) + "x" + std::to_string(height));
}

/// Encodes 16-bit samples (host order, `channels` per pixel) written big-endian, as colour type `color_type`.
std::vector<uint8_t> encode16(std::span<const uint16_t> samples, int width, int height, size_t channels,
                              uint8_t color_type, PngOptions options) {
  thread_local std::vector<uint8_t> big_endian_scratch;
  uint8_t* big_endian = scratch(big_endian_scratch, samples.size() * 2);
  for (size_t i = 0; i < samples.size(); ++i) {
    big_endian[2 * i] = uint8_t(samples[i] >> 8);
    big_endian[2 * i + 1] = uint8_t(samples[i]);
  }
  return encode(big_endian, width, height, 2 * channels, 16, color_type, options);
}

}  // namespace

std::vector<uint8_t> encode_png_grey8(std::span<const uint8_t> pixels, int width, int height, PngOptions options) {
  check_size(pixels.size(), width, height, 1, "encode_png_grey8");
  return encode(pixels.data(), width, height, 1, 8, 0, options);
}

std::vector<uint8_t> encode_png_rgb8(std::span<const uint8_t> rgb, int width, int height, PngOptions options) {
  check_size(rgb.size(), width, height, 3, "encode_png_rgb8");
  return encode(rgb.data(), width, height, 3, 8, 2, options);
}

std::vector<uint8_t> encode_png_grey16(std::span<const uint16_t> pixels, int width, int height,
                                       PngOptions options) {
  check_size(pixels.size(), width, height, 1, "encode_png_grey16");
  return encode16(pixels, width, height, 1, 0, options);
}

std::vector<uint8_t> encode_png_rgb16(std::span<const uint16_t> rgb, int width, int height, PngOptions options) {
  check_size(rgb.size(), width, height, 3, "encode_png_rgb16");
  return encode16(rgb, width, height, 3, 2, options);
}

}  // namespace silva::io
