/// @file PNG structure check (see png_check.hpp).
#include "core/png_check.hpp"

#include <algorithm>
#include <array>
#include <memory>
#include <new>
#include <vector>

#include <libdeflate.h>

#include "core/error.hpp"
#include "core/input_limits.hpp"

namespace silva {

namespace {

constexpr std::array<uint8_t, 8> kSignature = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

/// Big-endian 32-bit value at `p`.
uint32_t be32(const uint8_t* p) { return uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | p[3]; }

/// The fields of IHDR that size the image data.
struct Header {
  uint32_t width = 0, height = 0;
  int bit_depth = 0, colour_type = 0, interlace = 0;

  /// Samples per pixel of the colour type.
  int channels() const { return colour_type == 0 || colour_type == 3 ? 1 : colour_type == 4 ? 2 : colour_type == 2 ? 3 : 4; }
  /// Bytes of one filtered row of `w` pixels, its filter byte included (0 for an empty pass).
  uint64_t row_bytes(uint64_t w) const { return w ? 1 + (w * uint64_t(channels() * bit_depth) + 7) / 8 : 0; }
};

/// Throws InputError unless IHDR's data is a valid header.
Header parse_header(const uint8_t* data, uint32_t length, const std::string& where) {
  if (length != 13) throw InputError(where + ": PNG header chunk IHDR is " + std::to_string(length) + " bytes, not 13");
  Header h;
  h.width = be32(data);
  h.height = be32(data + 4);
  h.bit_depth = data[8];
  h.colour_type = data[9];
  h.interlace = data[12];
  if (h.width == 0 || h.height == 0 || h.width > uint32_t(limits::kMaxTextureSide) ||
      h.height > uint32_t(limits::kMaxTextureSide))
    throw InputError(where + ": PNG image is " + std::to_string(h.width) + "x" + std::to_string(h.height) +
                     " pixels (1 to " + std::to_string(limits::kMaxTextureSide) + " per side)");
  const int d = h.bit_depth;
  const bool depth_ok = h.colour_type == 0   ? (d == 1 || d == 2 || d == 4 || d == 8 || d == 16)
                        : h.colour_type == 3 ? (d == 1 || d == 2 || d == 4 || d == 8)
                        : (h.colour_type == 2 || h.colour_type == 4 || h.colour_type == 6) && (d == 8 || d == 16);
  if (!depth_ok)
    throw InputError(where + ": PNG colour type " + std::to_string(h.colour_type) + " with bit depth " +
                     std::to_string(d) + " is not a valid combination");
  if (data[10] != 0 || data[11] != 0 || h.interlace > 1)
    throw InputError(where + ": PNG compression, filter or interlace method is not one PNG defines");
  return h;
}

/// One pass of an image's rows: the pixels at (x0 + k·dx, y0 + m·dy).
struct Pass {
  uint32_t x0, y0, dx, dy;
};
/// The seven Adam7 passes of an interlaced image.
constexpr Pass kAdam7[7] = {{0, 0, 8, 8}, {4, 0, 8, 8}, {0, 4, 4, 8}, {2, 0, 4, 4}, {0, 2, 2, 4}, {1, 0, 2, 2}, {0, 1, 1, 2}};
/// The single pass of a non-interlaced image.
constexpr Pass kWhole[1] = {{0, 0, 1, 1}};

/// The passes of `h`'s image data, in file order.
std::span<const Pass> passes(const Header& h) { return h.interlace ? std::span<const Pass>(kAdam7) : std::span<const Pass>(kWhole); }

/// Pixels per row of pass `p` of `h`.
uint64_t pass_width(const Header& h, const Pass& p) { return h.width > p.x0 ? (h.width - p.x0 + p.dx - 1) / p.dx : 0; }
/// Rows of pass `p` of `h`.
uint64_t pass_rows(const Header& h, const Pass& p) { return h.height > p.y0 ? (h.height - p.y0 + p.dy - 1) / p.dy : 0; }

/// Bytes of the inflated image data of `h` (every pass's rows with their filter bytes).
uint64_t image_bytes(const Header& h) {
  uint64_t total = 0;
  for (const Pass& p : passes(h)) total += pass_rows(h, p) * h.row_bytes(pass_width(h, p));
  return total;
}

/// Throws InputError unless every filtered row of `image` (inflated IDAT of `h`) starts with a filter
/// type in 0..4.
void check_row_filters(const Header& h, std::span<const uint8_t> image, const std::string& where) {
  size_t at = 0;
  for (const Pass& p : passes(h)) {
    const uint64_t row = h.row_bytes(pass_width(h, p)), rows = pass_rows(h, p);
    for (uint64_t r = 0; r < rows && row; ++r, at += row)
      if (image[at] > 4)
        throw InputError(where + ": PNG row " + std::to_string(r) + " has filter type " + std::to_string(image[at]) +
                         " (0 to 4)");
  }
}

}  // namespace

bool is_png(std::span<const uint8_t> bytes) {
  return bytes.size() >= kSignature.size() && std::equal(kSignature.begin(), kSignature.end(), bytes.begin());
}

void check_png(std::span<const uint8_t> bytes, const std::string& where) {
  if (!is_png(bytes)) throw InputError(where + ": not a PNG file (no PNG signature)");
  Header header;
  bool have_header = false, have_palette = false, idat_done = false, ended = false;
  std::vector<uint8_t> zlib;
  size_t at = kSignature.size();
  // The header's claims first: a huge or impossible image is refused whatever follows it.
  if (bytes.size() >= at + 8 + 13 && be32(&bytes[at]) == 13 && std::equal(&bytes[at + 4], &bytes[at + 8], "IHDR"))
    parse_header(&bytes[at + 8], 13, where);
  while (!ended) {
    if (bytes.size() - at < 12) throw InputError(where + ": PNG ends inside a chunk (truncated file)");
    const uint32_t length = be32(&bytes[at]);
    const std::string type(reinterpret_cast<const char*>(&bytes[at + 4]), 4);
    if (length > bytes.size() - at - 12)
      throw InputError(where + ": PNG chunk " + type + " runs past the end of the file (truncated or corrupt)");
    const uint8_t* data = &bytes[at + 8];
    if (libdeflate_crc32(0, &bytes[at + 4], size_t(length) + 4) != be32(data + length))
      throw InputError(where + ": PNG chunk " + type + " fails its CRC (the file is corrupt)");
    if (!have_header && type != "IHDR") throw InputError(where + ": PNG does not start with its IHDR chunk");
    if (type == "IHDR") {
      if (have_header) throw InputError(where + ": PNG has a second IHDR chunk");
      header = parse_header(data, length, where);
      have_header = true;
    } else if (type == "PLTE") {
      have_palette = true;
    } else if (type == "IDAT") {
      if (idat_done) throw InputError(where + ": PNG's IDAT chunks are not consecutive");
      zlib.insert(zlib.end(), data, data + length);
    } else if (type == "IEND") {
      ended = true;
    } else if (!(type[0] & 0x20)) {
      throw InputError(where + ": PNG has an unknown critical chunk '" + limits::quoted_prefix(type) + "'");
    }
    if (type != "IDAT" && !zlib.empty()) idat_done = true;
    at += size_t(length) + 12;
  }
  if (header.colour_type == 3 && !have_palette) throw InputError(where + ": palette PNG without a PLTE chunk");
  if (zlib.empty()) throw InputError(where + ": PNG has no image data (IDAT)");
  std::vector<uint8_t> image(image_bytes(header));
  struct Free {
    void operator()(libdeflate_decompressor* d) const { libdeflate_free_decompressor(d); }
  };
  const std::unique_ptr<libdeflate_decompressor, Free> inflater(libdeflate_alloc_decompressor());
  if (!inflater) throw std::bad_alloc();
  if (libdeflate_zlib_decompress(inflater.get(), zlib.data(), zlib.size(), image.data(), image.size(), nullptr) !=
      LIBDEFLATE_SUCCESS)
    throw InputError(where + ": PNG image data does not inflate to its " + std::to_string(header.width) + "x" +
                     std::to_string(header.height) + " pixels (corrupt IDAT)");
  check_row_filters(header, image, where);
}

}  // namespace silva
