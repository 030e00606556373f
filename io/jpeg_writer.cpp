#include "io/jpeg_writer.hpp"

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "io/image_codecs.hpp"

namespace silva::io {

std::vector<uint8_t> encode_jpeg_rgb8(std::span<const uint8_t> rgb, int width, int height, int quality) {
  if (rgb.size() != size_t(width) * size_t(height) * 3)
    throw std::invalid_argument("encode_jpeg_rgb8: buffer size does not match width x height x 3");
  const cv::Mat view(height, width, CV_8UC3, const_cast<uint8_t*>(rgb.data()));
  cv::Mat bgr;
  cv::cvtColor(view, bgr, cv::COLOR_RGB2BGR);
  std::vector<uint8_t> jpeg;
  if (!encode_image(".jpg", bgr, jpeg, {cv::IMWRITE_JPEG_QUALITY, quality}))
    throw std::runtime_error("encode_jpeg_rgb8: OpenCV could not encode the image");
  return jpeg;
}

std::vector<uint8_t> jpeg_round_trip(std::span<const uint8_t> rgb, int width, int height, int quality) {
  const std::vector<uint8_t> jpeg = encode_jpeg_rgb8(rgb, width, height, quality);
  const cv::Mat bgr = decode_image(jpeg, cv::IMREAD_COLOR);
  if (bgr.rows != height || bgr.cols != width) throw std::runtime_error("jpeg_round_trip: OpenCV could not decode its JPEG");
  cv::Mat out_rgb;
  cv::cvtColor(bgr, out_rgb, cv::COLOR_BGR2RGB);
  return std::vector<uint8_t>(out_rgb.data, out_rgb.data + out_rgb.total() * 3);
}

}  // namespace silva::io
