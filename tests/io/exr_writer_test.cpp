#include "io/exr_writer.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <limits>

#include "io_test_util.hpp"

namespace silva::io {
namespace {

std::vector<float> depth_like(int w, int h) {
  std::vector<float> v(size_t(w) * h);
  for (size_t i = 0; i < v.size(); ++i) v[i] = (i % 9 == 0) ? 0.0f : 0.05f + 0.731f * float(i % 397) + 1e-3f * float(i);
  v[1] = 149.99f;
  v[2] = std::numeric_limits<float>::min();
  return v;
}

void expect_exact(const cv::Mat& m, const std::vector<float>& v, int w, int h) {
  ASSERT_EQ(m.type(), CV_32FC1);
  ASSERT_EQ(m.cols, w);
  ASSERT_EQ(m.rows, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float got = m.at<float>(y, x), want = v[size_t(y) * w + x];
      ASSERT_EQ(std::memcmp(&got, &want, 4), 0) << x << "," << y << ": " << got << " vs " << want;
    }
}

TEST(ExrWriter, RoundTripsExactlyThroughOpenCv) {
  const auto dir = test::scratch_dir("exr_roundtrip");
  for (auto [w, h] : {std::pair{37, 53}, std::pair{16, 16}, std::pair{5, 1}, std::pair{300, 33}}) {
    const auto v = depth_like(w, h);
    for (int level : {1, 6}) expect_exact(test::write_and_read(dir, "d.exr", encode_exr_y(v, w, h, level)), v, w, h);
  }
}

TEST(ExrWriter, SmoothDepthIsZipCompressed) {
  const auto dir = test::scratch_dir("exr_zip");
  const int w = 128, h = 40;
  std::vector<float> v(size_t(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) v[size_t(y) * w + x] = y < 10 ? 0.0f : 100.0f / float(y);  // sky + ground rows
  const auto exr = encode_exr_y(v, w, h);
  EXPECT_LT(exr.size(), v.size() * 4 / 8);
  expect_exact(test::write_and_read(dir, "z.exr", exr), v, w, h);
}

TEST(ExrWriter, IncompressibleBlocksAreStoredRawAndStillRead) {
  const auto dir = test::scratch_dir("exr_raw");
  const int w = 64, h = 20;
  std::vector<float> v(size_t(w) * h);
  uint32_t s = 12345;
  for (float& f : v) {
    s = s * 1664525u + 1013904223u;
    f = float(s >> 8) * 1e-3f;
  }
  expect_exact(test::write_and_read(dir, "n.exr", encode_exr_y(v, w, h)), v, w, h);
}

TEST(ExrWriter, HeaderNamesChannelYAndIsDeterministic) {
  const auto v = depth_like(20, 20);
  const auto a = encode_exr_y(v, 20, 20);
  EXPECT_EQ(a, encode_exr_y(v, 20, 20));
  ASSERT_GT(a.size(), 40u);
  EXPECT_EQ((std::vector<uint8_t>(a.begin(), a.begin() + 8)), (std::vector<uint8_t>{0x76, 0x2f, 0x31, 0x01, 2, 0, 0, 0}));
  const std::string header(a.begin(), a.begin() + 40);
  EXPECT_EQ(header.substr(8, 16), std::string("channels\0chlist\0", 16));
  EXPECT_EQ(header.substr(28, 2), std::string("Y\0", 2));
}

}  // namespace
}  // namespace silva::io
