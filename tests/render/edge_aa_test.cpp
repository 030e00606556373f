#include "render/edge_aa.hpp"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <stdexcept>

namespace silva::render {
namespace {

/// A w x h grey image (R = G = B) from a function of (x, y).
template <typename Fn>
std::vector<uint8_t> grey(int w, int h, Fn value) {
  std::vector<uint8_t> img(size_t(w) * h * 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int k = 0; k < 3; ++k) img[(size_t(y) * w + x) * 3 + k] = uint8_t(value(x, y));
  return img;
}

uint8_t at(const std::vector<uint8_t>& img, int w, int x, int y) { return img[(size_t(y) * w + x) * 3]; }

TEST(EdgeAa, FlatAndGentleGradientsAreUntouched) {
  std::vector<uint8_t> out;
  const auto flat = grey(16, 12, [](int, int) { return 90; });
  smooth_edges(flat, 16, 12, out);
  EXPECT_EQ(out, flat);
  const auto ramp = grey(16, 12, [](int x, int y) { return 40 + 3 * x + 2 * y; });  // contrast < 8 everywhere
  smooth_edges(ramp, 16, 12, out);
  EXPECT_EQ(out, ramp);
}

TEST(EdgeAa, IsolatedBrightPixelKnownAnswers) {
  // White pixel in black: blended 3/8 towards black (255 * 5/8 = 159.4 -> 159); the pixel below it
  // stands out by t = 1/6, eased 0.0741, blend 0.0278 towards white: 7.08 -> 7.
  const auto img = grey(9, 9, [](int x, int y) { return x == 4 && y == 4 ? 255 : 0; });
  std::vector<uint8_t> out;
  smooth_edges(img, 9, 9, out);
  EXPECT_EQ(at(out, 9, 4, 4), 159);
  EXPECT_EQ(at(out, 9, 4, 5), 7);
  EXPECT_EQ(at(out, 9, 5, 4), 7);
  EXPECT_EQ(at(out, 9, 0, 0), 0);
  EXPECT_EQ(at(out, 9, 2, 2), 0);  // no contrast in its cross
}

TEST(EdgeAa, StaircaseIsSoftenedWithoutOvershoot) {
  // A shallow dark/bright edge y = x / 4 rendered without antialiasing has hard steps.
  const int w = 32, h = 16;
  const auto img = grey(w, h, [](int x, int y) { return 4 * y > x ? 200 : 30; });
  std::vector<uint8_t> out;
  smooth_edges(img, w, h, out);
  int changed = 0;
  for (int y = 1; y + 1 < h; ++y)
    for (int x = 1; x + 1 < w; ++x) {
      const uint8_t v = at(out, w, x, y);
      EXPECT_GE(v, 30);
      EXPECT_LE(v, 200);
      changed += v != at(img, w, x, y);
    }
  EXPECT_GT(changed, 8);  // the step pixels along the edge moved towards the other side
}

TEST(EdgeAa, SameBytesForOneAndTwoThreads) {
  const int w = 97, h = 61;
  std::vector<uint8_t> img(size_t(w) * h * 3);
  for (size_t i = 0; i < img.size(); ++i) img[i] = uint8_t((i * 2654435761u) >> 13);
  std::vector<uint8_t> one, two;
  tbb::task_arena(1).execute([&] { smooth_edges(img, w, h, one); });
  tbb::task_arena(2).execute([&] { smooth_edges(img, w, h, two); });
  EXPECT_EQ(one, two);
  EXPECT_NE(one, img);
}

TEST(EdgeAa, MismatchedBufferIsRefused) {
  std::vector<uint8_t> out;
  EXPECT_THROW(smooth_edges(std::vector<uint8_t>(10), 4, 4, out), std::invalid_argument);
}

}  // namespace
}  // namespace silva::render
