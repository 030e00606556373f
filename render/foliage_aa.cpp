#include "render/foliage_aa.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <limits>

namespace silva::render {

namespace {

/// Depth of pixel i for layer tests: metric z, or infinity where nothing was hit.
float layer_depth(const GBuffer& g, size_t i) {
  return g.depth[i] > 0.0f ? g.depth[i] : std::numeric_limits<float>::infinity();
}

/// Weight of radiance `c` in a blend at `exposure`: 1 / (1 + exposed luminance).
float tone_weight(const Vec3f& c, float exposure) {
  return 1.0f / (1.0f + exposure * (0.2126f * c.x() + 0.7152f * c.y() + 0.0722f * c.z()));
}

/// The coverage blend of pixel (u, v) of `in` (see blend_minified_masks).
Vec3f blend_pixel(const GBuffer& g, const LinearFrame& in, const std::vector<float>& weight, float exposure, int u,
                  int v) {
  const size_t p = size_t(v) * size_t(g.width) + size_t(u);
  const float dp = layer_depth(g, p);
  const float centre = 4.0f * tone_weight(in.rgb[p], exposure);
  Vec3f sum = in.rgb[p] * centre;
  float total = centre;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const int x = u + dx, y = v + dy;
      if ((dx == 0 && dy == 0) || x < 0 || y < 0 || x >= g.width || y >= g.height) continue;
      const size_t q = size_t(y) * size_t(g.width) + size_t(x);
      const float dq = layer_depth(g, q);
      const float behind = g.depth[q] > 0.0f && dq >= dp * (1.0f - kLayerTolerance) ? weight[p] : 0.0f;
      const float in_front = dq <= dp * (1.0f + kLayerTolerance) ? weight[q] : 0.0f;
      const float w =
          float((dx == 0 || dy == 0) ? 2 : 1) * std::max(behind, in_front) * tone_weight(in.rgb[q], exposure);
      sum += in.rgb[q] * w;
      total += w;
    }
  return sum / total;
}

}  // namespace

float minified_weight(float mask_texels) {
  return std::clamp((mask_texels - kMinifiedStart) / (kMinifiedFull - kMinifiedStart), 0.0f, 1.0f);
}

bool has_minified_masks(const GBuffer& g) {
  return std::any_of(g.mask_texels.begin(), g.mask_texels.end(), [](float m) { return m > kMinifiedStart; });
}

void blend_minified_masks(const GBuffer& g, float exposure, LinearFrame& frame, LinearFrame& scratch) {
  std::vector<float> weight(g.size());
  std::transform(g.mask_texels.begin(), g.mask_texels.end(), weight.begin(), minified_weight);
  scratch.resize(frame.width, frame.height);
  tbb::parallel_for(tbb::blocked_range<int>(0, g.height), [&](const tbb::blocked_range<int>& rows) {
    for (int v = rows.begin(); v < rows.end(); ++v)
      for (int u = 0; u < g.width; ++u) {
        const size_t p = size_t(v) * size_t(g.width) + size_t(u);
        // Untouched unless a minified mask lies within one pixel.
        bool near_mask = false;
        for (int y = std::max(v - 1, 0); y <= std::min(v + 1, g.height - 1) && !near_mask; ++y)
          for (int x = std::max(u - 1, 0); x <= std::min(u + 1, g.width - 1); ++x)
            near_mask |= weight[size_t(y) * size_t(g.width) + size_t(x)] > 0.0f;
        scratch.rgb[p] = near_mask ? blend_pixel(g, frame, weight, exposure, u, v) : frame.rgb[p];
      }
  });
  std::swap(frame.rgb, scratch.rgb);
}

}  // namespace silva::render
