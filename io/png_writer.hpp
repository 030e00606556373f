#pragma once
/// @file A small byte-deterministic PNG encoder around libdeflate (8-bit grey, 8-bit RGB,
/// 16-bit grey, 16-bit RGB). One row filter for every row and one zlib stream; the defaults were chosen
/// by bench/encode_bench.cpp (see bench/README.md "Encoders").
#include <cstdint>
#include <span>
#include <vector>

namespace silva::io {

/// PNG row filter applied to every row (PNG spec filter types 0..4).
enum class PngFilter : uint8_t { None = 0, Sub = 1, Up = 2, Average = 3, Paeth = 4 };

/// Encoder settings; the defaults are the measured best speed/size trade-off.
struct PngOptions {
  PngFilter filter = PngFilter::Up;   ///< Row filter (Up: fastest on RGB, smallest on labels).
  int level = 1;                      ///< libdeflate level 0..12.
};

/// Encodes width x height 8-bit grey pixels (row-major) as a PNG file image.
std::vector<uint8_t> encode_png_grey8(std::span<const uint8_t> pixels, int width, int height,
                                      PngOptions options = {});

/// Encodes width x height interleaved R, G, B bytes (row-major) as an 8-bit RGB PNG.
std::vector<uint8_t> encode_png_rgb8(std::span<const uint8_t> rgb, int width, int height,
                                     PngOptions options = {});

/// Encodes width x height 16-bit grey values (host order; written big-endian) as a PNG.
std::vector<uint8_t> encode_png_grey16(std::span<const uint16_t> pixels, int width, int height,
                                       PngOptions options = {});

/// Encodes width x height interleaved 16-bit R, G, B values (host order; written big-endian) as a PNG.
std::vector<uint8_t> encode_png_rgb16(std::span<const uint16_t> rgb, int width, int height, PngOptions options = {});

}  // namespace silva::io
