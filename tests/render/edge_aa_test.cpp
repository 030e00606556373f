#include "render/edge_aa.hpp"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "highway_targets.hpp"

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

/// The filter written pixel by pixel in plain scalar code: the reference for the SIMD row version.
std::vector<uint8_t> reference_smooth(const std::vector<uint8_t>& img, int w, int h) {
  std::vector<uint8_t> out = img;
  const auto luma = [&](int x, int y) {
    const uint8_t* p = &img[(size_t(y) * w + x) * 3];
    return (2.0f * float(p[0]) + 5.0f * float(p[1]) + float(p[2])) * 0.125f;
  };
  for (int y = 1; y + 1 < h; ++y)
    for (int x = 1; x + 1 < w; ++x) {
      const float lc = luma(x, y), ln = luma(x, y - 1), ls = luma(x, y + 1), le = luma(x + 1, y), lw = luma(x - 1, y);
      const float hi = std::max({lc, ln, ls, le, lw}), lo = std::min({lc, ln, ls, le, lw});
      const float contrast = hi - lo;
      if (contrast < std::max(8.0f, 0.125f * hi)) continue;
      const float lne = luma(x + 1, y - 1), lnw = luma(x - 1, y - 1), lse = luma(x + 1, y + 1), lsw = luma(x - 1, y + 1);
      const float rows = 2.0f * std::abs(ln + ls - 2.0f * lc) + std::abs(lne + lse - 2.0f * le) + std::abs(lnw + lsw - 2.0f * lw);
      const float cols = 2.0f * std::abs(le + lw - 2.0f * lc) + std::abs(lne + lnw - 2.0f * ln) + std::abs(lse + lsw - 2.0f * ls);
      int ox = 0, oy = 0;
      float best = -1.0f;
      const auto consider = [&](int dx, int dy, float l) {
        if (std::abs(l - lc) > best) best = std::abs(l - lc), ox = dx, oy = dy;
      };
      if (rows >= cols) consider(0, -1, ln), consider(0, 1, ls);
      if (cols >= rows) consider(1, 0, le), consider(-1, 0, lw);
      const float average = (2.0f * (ln + ls + le + lw) + lne + lnw + lse + lsw) / 12.0f;
      const float t = std::min(std::abs(average - lc) / contrast, 1.0f);
      const float blend = 0.375f * (t * t * (3.0f - 2.0f * t));
      for (int k = 0; k < 3; ++k) {
        const float c = img[(size_t(y) * w + x) * 3 + k], o = img[(size_t(y + oy) * w + x + ox) * 3 + k];
        const float v = c + blend * (o - c);
        out[(size_t(y) * w + x) * 3 + k] = uint8_t(int(v + 0.5f));  // NOLINT(bugprone-incorrect-roundings): v >= 0
      }
    }
  return out;
}

TEST(EdgeAa, MatchesThePixelByPixelFilterOnEveryHighwayTarget) {
  // Noise (almost every pixel an edge), blocks with hard edges and flat areas, odd sizes so that
  // rows end inside a vector.
  const int w = 101, h = 37;
  std::vector<uint8_t> img(size_t(w) * h * 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int k = 0; k < 3; ++k) {
        const size_t i = (size_t(y) * w + x) * 3 + size_t(k);
        img[i] = x < 50 ? uint8_t((i * 2654435761u) >> 13) : uint8_t(((x / 7 + y / 5) % 3) * 90 + 20 * k);
      }
  const std::vector<uint8_t> want = reference_smooth(img, w, h);
  ASSERT_NE(want, img);
  for (int64_t target : test::highway_targets()) {
    const test::PinnedTarget pin(target);
    SCOPED_TRACE(hwy::TargetName(target));
    std::vector<uint8_t> got;
    smooth_edges(img, w, h, got);
    EXPECT_EQ(got, want);
  }
}

TEST(EdgeAa, MismatchedBufferIsRefused) {
  std::vector<uint8_t> out;
  EXPECT_THROW(smooth_edges(std::vector<uint8_t>(10), 4, 4, out), std::invalid_argument);
}

}  // namespace
}  // namespace silva::render
