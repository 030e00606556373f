#pragma once
/// @file NumPy's .npy format (version 1.0), as np.load reads it: the arrays of the tartanair export.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace silva::io {

/// A C-order .npy file of `shape` holding `data` (its bytes, little-endian), whose element type is NumPy's `descr`
/// ("<f4", "|u1", ...); the header is padded to a multiple of 64 bytes as NumPy writes it.
std::vector<uint8_t> npy_file(const std::string& descr, std::span<const size_t> shape, std::span<const uint8_t> data);

}  // namespace silva::io
