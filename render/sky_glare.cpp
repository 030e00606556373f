#include "render/sky_glare.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace silva::render {

namespace {

/// Blocks of `pixels` pixels of `block` pixels each (the last one partial).
int blocks_of(int pixels, int block) { return (pixels + block - 1) / block; }

/// Runs row(y) for y in [0, rows), in parallel.
template <class Row>
void each_row(int rows, Row row) {
  tbb::parallel_for(tbb::blocked_range<int>(0, rows), [&](const tbb::blocked_range<int>& r) {
    for (int y = r.begin(); y < r.end(); ++y) row(y);
  });
}

/// The sky's light per kGlareBlock block of `g`: the share of the block's pixels that see the sky times the
/// sky's radiance towards the block's centre, each channel capped at kGlareSourceCap x the mean sky radiance.
LinearFrame sky_source(const GBuffer& g, const Camera& camera, const Sky& sky) {
  LinearFrame s;
  s.resize(blocks_of(g.width, kGlareBlock), blocks_of(g.height, kGlareBlock));
  const Vec3f cap = sky.mean_radiance * kGlareSourceCap;
  each_row(s.height, [&](int by) {
    for (int bx = 0; bx < s.width; ++bx) {
      const int u0 = bx * kGlareBlock, v0 = by * kGlareBlock;
      const int u1 = std::min(u0 + kGlareBlock, g.width), v1 = std::min(v0 + kGlareBlock, g.height);
      int open = 0;
      for (int v = v0; v < v1; ++v)
        for (int u = u0; u < u1; ++u) open += g.depth[size_t(v) * size_t(g.width) + size_t(u)] == 0.0f ? 1 : 0;
      Vec3f& out = s.rgb[size_t(by) * size_t(s.width) + size_t(bx)];
      out = Vec3f::Zero();
      if (open == 0) continue;
      const double x = (0.5 * double(u0 + u1) - camera.cx) / camera.fx, y = (0.5 * double(v0 + v1) - camera.cy) / camera.fy;
      const Vec3f dir = camera.world_direction(x, y).normalized().cast<float>();
      const float share = float(open) / float((u1 - u0) * (v1 - v0));
      out = sky.radiance(dir).cwiseMin(cap) * share;
    }
  });
  return s;
}

/// `src` averaged over squares of `factor` x `factor` of its texels, then blurred by a Gaussian of one texel
/// of the result (7 taps, edges clamped), horizontally then vertically.
LinearFrame coarse_blur(const LinearFrame& src, int factor) {
  LinearFrame mean;
  mean.resize(blocks_of(src.width, factor), blocks_of(src.height, factor));
  each_row(mean.height, [&](int y) {
    for (int x = 0; x < mean.width; ++x) {
      Vec3f sum = Vec3f::Zero();
      int n = 0;
      for (int v = y * factor; v < std::min((y + 1) * factor, src.height); ++v)
        for (int u = x * factor; u < std::min((x + 1) * factor, src.width); ++u, ++n) sum += src.at(u, v);
      mean.rgb[size_t(y) * size_t(mean.width) + size_t(x)] = sum / float(n);
    }
  });
  constexpr std::array<float, 4> kTaps = {0.39894228f, 0.24197072f, 0.05399097f, 0.00443185f};  // exp(-k^2/2)/sqrt(2 pi)
  constexpr float kNorm = kTaps[0] + 2.0f * (kTaps[1] + kTaps[2] + kTaps[3]);
  const auto pass = [&](const LinearFrame& in, int dx, int dy) {
    LinearFrame out;
    out.resize(in.width, in.height);
    each_row(in.height, [&](int y) {
      for (int x = 0; x < in.width; ++x) {
        Vec3f sum = in.at(x, y) * kTaps[0];
        for (int k = 1; k < 4; ++k) sum += (in.at(x - k * dx, y - k * dy) + in.at(x + k * dx, y + k * dy)) * kTaps[size_t(k)];
        out.rgb[size_t(y) * size_t(in.width) + size_t(x)] = sum / kNorm;
      }
    });
    return out;
  };
  return pass(pass(mean, 1, 0), 0, 1);
}

}  // namespace

SkyGlare::SkyGlare(const GBuffer& g, const Camera& camera, const Sky& sky, float strength) : g_(g), strength_(strength) {
  if (!(strength > 0.0f)) return;
  const LinearFrame source = sky_source(g, camera, sky);
  if (std::all_of(source.rgb.begin(), source.rgb.end(), [](const Vec3f& c) { return c.isZero(); })) return;  // no sky
  halo_.resize(source.width, source.height);
  std::fill(halo_.rgb.begin(), halo_.rgb.end(), Vec3f::Zero());
  for (int level = 0; level < kGlareLevels; ++level) {
    const int factor = kGlareLevelBlocks[level];
    const LinearFrame blurred = coarse_blur(source, factor);
    each_row(halo_.height, [&](int y) {
      for (int x = 0; x < halo_.width; ++x)
        halo_.rgb[size_t(y) * size_t(halo_.width) + size_t(x)] +=
            blurred.bilinear((float(x) + 0.5f) / float(factor), (float(y) + 0.5f) / float(factor)) * kGlareLevelWeights[level];
    });
  }
  columns_.resize(size_t(g.width));
  for (int u = 0; u < g.width; ++u) {
    const float fx = (float(u) + 0.5f) / float(kGlareBlock) - 0.5f, x0 = std::floor(fx);
    columns_[size_t(u)] = {std::clamp(int(x0), 0, halo_.width - 1), std::clamp(int(x0) + 1, 0, halo_.width - 1), fx - x0};
  }
  active_ = true;
}

void SkyGlare::apply_row(int v, Vec3f* radiance) const {
  // The halo's two block rows around this pixel row, interpolated in y once for the row.
  const float fy = (float(v) + 0.5f) / float(kGlareBlock) - 0.5f, y0 = std::floor(fy), ay = fy - y0;
  std::vector<Vec3f> row(size_t(halo_.width));
  for (int x = 0; x < halo_.width; ++x) row[size_t(x)] = halo_.at(x, int(y0)) * (1.0f - ay) + halo_.at(x, int(y0) + 1) * ay;
  const size_t first = size_t(v) * size_t(g_.width);
  for (int u = 0; u < g_.width; ++u) {
    const Column& c = columns_[size_t(u)];
    const Vec3f halo = row[size_t(c.left)] * (1.0f - c.weight) + row[size_t(c.right)] * c.weight;
    Vec3f& l = radiance[u];
    l = g_.depth[first + size_t(u)] == 0.0f ? Vec3f(l + (halo - l) * strength_) : Vec3f(l + halo * strength_);
  }
}

}  // namespace silva::render
