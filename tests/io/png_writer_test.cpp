#include "io/png_writer.hpp"

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include "io_test_util.hpp"

namespace silva::io {
namespace {

std::vector<uint8_t> pattern(size_t n, uint32_t seed) {
  std::vector<uint8_t> v(n);
  uint32_t s = seed;
  for (size_t i = 0; i < n; ++i) {
    s = s * 1664525u + 1013904223u;
    v[i] = uint8_t((i % 7 == 0) ? (s >> 24) : (i * 31 / 17));
  }
  return v;
}

constexpr PngFilter kFilters[] = {PngFilter::None, PngFilter::Sub, PngFilter::Up, PngFilter::Average, PngFilter::Paeth};

TEST(PngWriter, Grey8RoundTripsWithEveryFilterAndLevel) {
  const auto dir = test::scratch_dir("png_grey8");
  const int w = 41, h = 13;
  const auto px = pattern(size_t(w) * h, 1);
  for (PngFilter f : kFilters)
    for (int level : {0, 1, 6, 12}) {
      const cv::Mat m = test::write_and_read(dir, "g.png", encode_png_grey8(px, w, h, {f, level}));
      ASSERT_EQ(m.type(), CV_8UC1);
      ASSERT_EQ(m.cols, w);
      ASSERT_EQ(m.rows, h);
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) ASSERT_EQ(m.at<uint8_t>(y, x), px[size_t(y) * w + x]) << int(f) << " " << level;
    }
}

TEST(PngWriter, Rgb8HoldsRgbInFileOrder) {
  const auto dir = test::scratch_dir("png_rgb8");
  const int w = 29, h = 17;
  const auto px = pattern(size_t(w) * h * 3, 2);
  for (PngFilter f : kFilters) {
    const cv::Mat m = test::write_and_read(dir, "c.png", encode_png_rgb8(px, w, h, {f, 1}));
    ASSERT_EQ(m.type(), CV_8UC3);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const cv::Vec3b bgr = m.at<cv::Vec3b>(y, x);
        const size_t i = (size_t(y) * w + x) * 3;
        ASSERT_EQ(bgr[2], px[i]);
        ASSERT_EQ(bgr[1], px[i + 1]);
        ASSERT_EQ(bgr[0], px[i + 2]);
      }
  }
}

TEST(PngWriter, Grey16IsBigEndianAndRoundTrips) {
  const auto dir = test::scratch_dir("png_grey16");
  const int w = 19, h = 11;
  std::vector<uint16_t> px(size_t(w) * h);
  for (size_t i = 0; i < px.size(); ++i) px[i] = uint16_t(i * 977 + (i % 3) * 40000);
  for (PngFilter f : kFilters) {
    const cv::Mat m = test::write_and_read(dir, "d.png", encode_png_grey16(px, w, h, {f, 1}));
    ASSERT_EQ(m.type(), CV_16UC1);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) ASSERT_EQ(m.at<uint16_t>(y, x), px[size_t(y) * w + x]);
  }
}

TEST(PngWriter, KnownHeaderBytes) {
  const std::vector<uint8_t> px = {0, 255};
  const auto png = encode_png_grey8(px, 2, 1);
  const std::vector<uint8_t> head(png.begin(), png.begin() + 33);
  const std::vector<uint8_t> expected = {0x89, 'P', 'N', 'G', 13, 10, 26, 10,  // signature
                                         0, 0, 0, 13, 'I', 'H', 'D', 'R',     // IHDR length + type
                                         0, 0, 0, 2, 0, 0, 0, 1, 8, 0, 0, 0, 0,  // 2x1, 8-bit grey
                                         0xd1, 0x49, 0x20, 0x56};            // CRC-32 of IHDR
  EXPECT_EQ(head, expected);
  const std::vector<uint8_t> tail(png.end() - 12, png.end());
  EXPECT_EQ(tail, (std::vector<uint8_t>{0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xae, 0x42, 0x60, 0x82}));
}

TEST(PngWriter, ByteIdenticalAcrossEncodes) {
  const int w = 64, h = 48;
  const auto px = pattern(size_t(w) * h * 3, 3);
  EXPECT_EQ(encode_png_rgb8(px, w, h), encode_png_rgb8(px, w, h));
}

TEST(PngWriter, RejectsMismatchedBuffer) {
  const std::vector<uint8_t> px(10);
  EXPECT_THROW(encode_png_grey8(px, 3, 3), std::invalid_argument);
  EXPECT_THROW(encode_png_rgb8(px, 0, 1), std::invalid_argument);
}

}  // namespace
}  // namespace silva::io
