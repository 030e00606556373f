#include "io/jpeg_writer.hpp"

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace silva::io {

std::vector<uint8_t> encode_jpeg_rgb8(std::span<const uint8_t> rgb, int width, int height, int quality) {
  if (rgb.size() != size_t(width) * size_t(height) * 3)
    throw std::invalid_argument("encode_jpeg_rgb8: buffer size does not match width x height x 3");
  const cv::Mat view(height, width, CV_8UC3, const_cast<uint8_t*>(rgb.data()));
  cv::Mat bgr;
  cv::cvtColor(view, bgr, cv::COLOR_RGB2BGR);
  std::vector<uint8_t> jpeg;
  if (!cv::imencode(".jpg", bgr, jpeg, {cv::IMWRITE_JPEG_QUALITY, quality}))
    throw std::runtime_error("encode_jpeg_rgb8: OpenCV could not encode the image");
  return jpeg;
}

}  // namespace silva::io
