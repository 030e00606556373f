// check_png: PNGs built here byte by byte (zlib from libdeflate, CRCs computed) pass; each kind of damage
// is refused with a line naming the file and what is wrong.
#include <gtest/gtest.h>

#include <libdeflate.h>

#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/png_check.hpp"

namespace silva {
namespace {

using Bytes = std::vector<uint8_t>;

void put32(Bytes& b, uint32_t v) {
  for (int s = 24; s >= 0; s -= 8) b.push_back(uint8_t(v >> s));
}

/// Appends chunk `type` with `data` and its CRC (or `crc_xor` applied to it).
void chunk(Bytes& png, const std::string& type, const Bytes& data, uint32_t crc_xor = 0) {
  put32(png, uint32_t(data.size()));
  Bytes body(type.begin(), type.end());
  body.insert(body.end(), data.begin(), data.end());
  png.insert(png.end(), body.begin(), body.end());
  put32(png, libdeflate_crc32(0, body.data(), body.size()) ^ crc_xor);
}

/// zlib stream of `raw`.
Bytes deflate(const Bytes& raw) {
  libdeflate_compressor* c = libdeflate_alloc_compressor(6);
  Bytes out(libdeflate_zlib_compress_bound(c, raw.size()));
  out.resize(libdeflate_zlib_compress(c, raw.data(), raw.size(), out.data(), out.size()));
  libdeflate_free_compressor(c);
  return out;
}

/// IHDR data.
Bytes header(uint32_t w, uint32_t h, uint8_t depth, uint8_t colour, uint8_t interlace = 0) {
  Bytes d;
  put32(d, w);
  put32(d, h);
  d.insert(d.end(), {depth, colour, 0, 0, interlace});
  return d;
}

/// A w x h 8-bit grey PNG whose rows use filter `filter` (pixels 0), with IDAT's `idat` replacing the
/// image data when given.
Bytes grey_png(uint32_t w, uint32_t h, uint8_t filter = 0, const Bytes* idat = nullptr) {
  Bytes raw;
  for (uint32_t y = 0; y < h; ++y) {
    raw.push_back(filter);
    raw.insert(raw.end(), w, uint8_t(y));
  }
  Bytes png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  chunk(png, "IHDR", header(w, h, 8, 0));
  chunk(png, "IDAT", idat ? *idat : deflate(raw));
  chunk(png, "IEND", {});
  return png;
}

/// The InputError message of check_png on `png`, or "" when it passes.
std::string refusal(const Bytes& png) {
  try {
    check_png(png, "x.png");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(PngCheck, WellFormedImagesPass) {
  EXPECT_EQ(refusal(grey_png(7, 5)), "");
  EXPECT_EQ(refusal(grey_png(1, 1, 4)), "");
  // An interlaced 16-bit RGBA image of 9 x 3 (8 bytes a pixel): the Adam7 passes' pixels per row and
  // rows are (2, 1) (1, 1) (0, 0) (2, 1) (5, 1) (4, 2) (9, 1); a pass without pixels has no rows.
  const int widths[7] = {2, 1, 0, 2, 5, 4, 9}, rows[7] = {1, 1, 0, 1, 1, 2, 1};
  Bytes raw;
  for (int p = 0; p < 7; ++p)
    for (int r = 0; r < rows[p]; ++r) {
      raw.push_back(0);
      raw.insert(raw.end(), size_t(widths[p]) * 8, 0);
    }
  Bytes png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  chunk(png, "IHDR", header(9, 3, 16, 6, 1));
  chunk(png, "tEXt", {'a', 0, 'b'});  // an ancillary chunk passes
  chunk(png, "IDAT", deflate(raw));
  chunk(png, "IEND", {});
  EXPECT_EQ(refusal(png), "");
  raw.push_back(0);  // one byte more than the passes hold
  Bytes longer = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  chunk(longer, "IHDR", header(9, 3, 16, 6, 1));
  chunk(longer, "IDAT", deflate(raw));
  chunk(longer, "IEND", {});
  EXPECT_NE(refusal(longer).find("does not inflate"), std::string::npos);
}

/// True when `message` names the file and holds `what`.
bool names(const std::string& message, const std::string& what) {
  return message.rfind("x.png: ", 0) == 0 && message.find(what) != std::string::npos;
}

TEST(PngCheck, EachKindOfDamageIsNamed) {
  const Bytes good = grey_png(7, 5);
  Bytes flipped = good;
  flipped[8 + 25 + 8 + 2] ^= 0x10;  // a byte of IDAT's data (after the signature and IHDR)
  EXPECT_TRUE(names(refusal(flipped), "PNG chunk IDAT fails its CRC")) << refusal(flipped);
  const Bytes truncated(good.begin(), good.end() - 20);
  EXPECT_TRUE(names(refusal(truncated), "truncated")) << refusal(truncated);
  const Bytes garbage = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10};  // CRC right, data not zlib
  EXPECT_TRUE(names(refusal(grey_png(7, 5, 0, &garbage)), "does not inflate to its 7x5 pixels"));
  EXPECT_TRUE(names(refusal(grey_png(7, 5, 7)), "row 0 has filter type 7 (0 to 4)"));
  const Bytes not_png = {'G', 'I', 'F', '8', '9', 'a', 0, 0, 0};
  EXPECT_TRUE(names(refusal(not_png), "no PNG signature"));

  Bytes sig = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  Bytes huge = sig, odd_depth = sig, unknown = sig, late = sig, palette = sig;
  chunk(huge, "IHDR", header(60000, 60000, 8, 0));
  chunk(huge, "IEND", {});
  EXPECT_TRUE(names(refusal(huge), "60000x60000 pixels (1 to 16384 per side)")) << refusal(huge);
  chunk(odd_depth, "IHDR", header(4, 4, 4, 2));
  EXPECT_TRUE(names(refusal(odd_depth), "colour type 2 with bit depth 4")) << refusal(odd_depth);
  chunk(unknown, "IHDR", header(1, 1, 8, 0));
  chunk(unknown, "ABCD", {});
  EXPECT_TRUE(names(refusal(unknown), "unknown critical chunk 'ABCD'")) << refusal(unknown);
  chunk(late, "IEND", {});
  EXPECT_TRUE(names(refusal(late), "does not start with its IHDR")) << refusal(late);
  chunk(palette, "IHDR", header(1, 1, 8, 3));
  chunk(palette, "IDAT", deflate({0, 0}));
  chunk(palette, "IEND", {});
  EXPECT_TRUE(names(refusal(palette), "palette PNG without a PLTE")) << refusal(palette);
}

}  // namespace
}  // namespace silva
