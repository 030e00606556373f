#pragma once
/// @file OpenCV's image encoders and decoders (imgcodecs), opened at the first image they handle
/// (core/imgcodecs_symbols.hpp says why): the same functions, the same bytes.
#include <cstdint>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace silva::io {

/// cv::imdecode of encoded image bytes with OpenCV's cv::IMREAD_* `flags` (empty when they are no image).
cv::Mat decode_image(cv::InputArray bytes, int flags);

/// cv::imread of the image file at `path` with OpenCV's cv::IMREAD_* `flags` (empty when unreadable).
cv::Mat read_image_file(const std::string& path, int flags);

/// cv::imencode of `image` in the format of `extension` (".png", ".jpg") with OpenCV's cv::IMWRITE_* `params`;
/// false when OpenCV cannot encode it.
bool encode_image(const std::string& extension, cv::InputArray image, std::vector<uint8_t>& out,
                  const std::vector<int>& params);

}  // namespace silva::io
