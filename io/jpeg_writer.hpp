#pragma once
/// @file JPEG encoding of 8-bit RGB images (OpenCV imencode), for previews streamed to a browser and
/// for a camera's compressed stream (jpeg_round_trip); dataset files are never JPEG.
#include <cstdint>
#include <span>
#include <vector>

namespace silva::io {

/// Encodes width x height interleaved R, G, B bytes (row-major) as a baseline JPEG of `quality` (1..100).
std::vector<uint8_t> encode_jpeg_rgb8(std::span<const uint8_t> rgb, int width, int height, int quality);

/// The same image after a JPEG of `quality` (1..100) was made of it and decoded again (libjpeg's exact
/// integer transforms: the same bytes on every machine), as interleaved R, G, B bytes.
std::vector<uint8_t> jpeg_round_trip(std::span<const uint8_t> rgb, int width, int height, int quality);

}  // namespace silva::io
