#pragma once
/// @file A structural check of PNG bytes before a decoder sees them: chunk layout and CRCs, the header's
/// fields, the image data's zlib stream and its row filters. A PNG that passes decodes without the
/// decoder's own complaints (libpng prints its errors on stderr before the caller can say anything).
#include <cstdint>
#include <span>
#include <string>

namespace silva {

/// True when `bytes` start with the PNG signature.
bool is_png(std::span<const uint8_t> bytes);

/// Throws InputError "<where>: <what is wrong>" unless `bytes` hold a well-formed PNG: signature, chunks
/// within the data with matching CRCs, IHDR first with a valid size, bit depth, colour type and
/// interlace method, PLTE where a palette image needs one, IDAT chunks together, IEND last, no unknown
/// critical chunk, and IDAT's zlib stream inflating to exactly the filtered image's size with every
/// row's filter type in 0..4. Images over limits::kMaxTextureSide a side are refused before inflating.
void check_png(std::span<const uint8_t> bytes, const std::string& where);

}  // namespace silva
