#pragma once
/// @file A small byte-deterministic OpenEXR writer for one float32 channel named "Y"
/// (single-part scanline file, ZIP compression of 16-line blocks via libdeflate).
#include <cstdint>
#include <span>
#include <vector>

namespace silva::io {

/// Encodes width x height float32 values (row-major) as an EXR file image with channel "Y".
/// `level` is the libdeflate level (1..12) for the ZIP blocks; a block that does not shrink is
/// stored raw, as the format allows.
std::vector<uint8_t> encode_exr_y(std::span<const float> values, int width, int height, int level = 1);

}  // namespace silva::io
