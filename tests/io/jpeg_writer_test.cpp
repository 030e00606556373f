#include "io/jpeg_writer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

namespace silva::io {
namespace {

/// A 64 x 48 image: a smooth colour gradient with a sharp-edged square in it.
std::vector<uint8_t> test_image() {
  std::vector<uint8_t> rgb(64 * 48 * 3);
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 64; ++x) {
      uint8_t* p = &rgb[size_t(y * 64 + x) * 3];
      const bool square = x >= 20 && x < 36 && y >= 12 && y < 28;
      p[0] = uint8_t(square ? 240 : 3 * x);
      p[1] = uint8_t(square ? 20 : 4 * y);
      p[2] = uint8_t(square ? 30 : 100);
    }
  return rgb;
}

/// Mean absolute difference of two byte images.
double mean_difference(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
  double sum = 0;
  for (size_t i = 0; i < a.size(); ++i) sum += std::abs(int(a[i]) - int(b[i]));
  return sum / double(a.size());
}

TEST(JpegRoundTrip, KeepsTheImageLosesDetailByQualityAndIsRepeatable) {
  const std::vector<uint8_t> in = test_image();
  const std::vector<uint8_t> fine = jpeg_round_trip(in, 64, 48, 95), coarse = jpeg_round_trip(in, 64, 48, 10);
  ASSERT_EQ(fine.size(), in.size());
  ASSERT_EQ(coarse.size(), in.size());
  EXPECT_NE(fine, in);                                             // compressed ...
  EXPECT_LT(mean_difference(fine, in), 3.0);                       // ... but the same picture
  EXPECT_GT(mean_difference(coarse, in), 2.0 * mean_difference(fine, in));  // quality matters
  EXPECT_EQ(jpeg_round_trip(in, 64, 48, 95), fine);                // same bytes each time
  // R stays R: the square is still red in the middle.
  const uint8_t* centre = &fine[size_t(20 * 64 + 28) * 3];
  EXPECT_GT(centre[0], 200);
  EXPECT_LT(centre[1], 60);
}

TEST(JpegRoundTrip, RefusesAWrongBufferSize) {
  const std::vector<uint8_t> short_buffer(10);
  EXPECT_THROW(jpeg_round_trip(short_buffer, 64, 48, 90), std::invalid_argument);
}

}  // namespace
}  // namespace silva::io
