#include "render/foliage_aa.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdint>
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

/// Per-pixel inputs of the blend, computed once: layer_depth, minified_weight, tone_weight and whether a
/// minified mask lies within one pixel along the row.
struct BlendPlanes {
  std::vector<float> layer, weight, tone;
  std::vector<uint8_t> row_near;
};

/// Adds neighbour q (tent weight `tent`) of a pixel at layer depth dp with blend weight wp to sum and total.
inline void add_neighbour(const LinearFrame& in, const BlendPlanes& b, size_t q, float tent, float dp, float wp,
                          Vec3f& sum, float& total) {
  const float dq = b.layer[q];
  const float behind = dq < std::numeric_limits<float>::infinity() && dq >= dp * (1.0f - kLayerTolerance) ? wp : 0.0f;
  const float in_front = dq <= dp * (1.0f + kLayerTolerance) ? b.weight[q] : 0.0f;
  const float w = tent * std::max(behind, in_front) * b.tone[q];
  sum += in.rgb[q] * w;
  total += w;
}

/// The coverage blend of pixel (u, v) of `in` (see blend_minified_masks).
Vec3f blend_pixel(const GBuffer& g, const LinearFrame& in, const BlendPlanes& b, int u, int v) {
  const size_t w = size_t(g.width), p = size_t(v) * w + size_t(u);
  const float dp = b.layer[p], wp = b.weight[p];
  Vec3f sum = in.rgb[p] * (4.0f * b.tone[p]);
  float total = 4.0f * b.tone[p];
  if (u > 0 && v > 0 && u + 1 < g.width && v + 1 < g.height) {  // inside: no bounds per neighbour
    for (const size_t q : {p - w, p - 1, p + 1, p + w}) add_neighbour(in, b, q, 2.0f, dp, wp, sum, total);
    for (const size_t q : {p - w - 1, p - w + 1, p + w - 1, p + w + 1}) add_neighbour(in, b, q, 1.0f, dp, wp, sum, total);
    return sum / total;
  }
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const int x = u + dx, y = v + dy;
      if ((dx == 0 && dy == 0) || x < 0 || y < 0 || x >= g.width || y >= g.height) continue;
      add_neighbour(in, b, size_t(y) * w + size_t(x), (dx == 0 || dy == 0) ? 2.0f : 1.0f, dp, wp, sum, total);
    }
  return sum / total;
}

/// True when a minified mask lies within one pixel of (u, v) (BlendPlanes::row_near of the rows around).
bool near_mask(const GBuffer& g, const BlendPlanes& b, int u, int v) {
  const size_t w = size_t(g.width), i = size_t(v) * w + size_t(u);
  return b.row_near[i] != 0 || (v > 0 && b.row_near[i - w] != 0) || (v + 1 < g.height && b.row_near[i + w] != 0);
}

/// Runs `row(v)` for every row of `g` in parallel.
template <class Row>
void each_row(const GBuffer& g, Row row) {
  tbb::parallel_for(tbb::blocked_range<int>(0, g.height), [&](const tbb::blocked_range<int>& rows) {
    for (int v = rows.begin(); v < rows.end(); ++v) row(v, size_t(v) * size_t(g.width));
  });
}

}  // namespace

float minified_weight(float mask_texels) {
  return std::clamp((mask_texels - kMinifiedStart) / (kMinifiedFull - kMinifiedStart), 0.0f, 1.0f);
}

bool has_minified_masks(const GBuffer& g) {
  return std::any_of(g.mask_texels.begin(), g.mask_texels.end(), [](float m) { return m > kMinifiedStart; });
}

void blend_minified_masks(const GBuffer& g, float exposure, LinearFrame& frame, LinearFrame& scratch) {
  BlendPlanes b{std::vector<float>(g.size()), std::vector<float>(g.size()), std::vector<float>(g.size()),
                std::vector<uint8_t>(g.size())};
  each_row(g, [&](int, size_t row) {
    for (size_t i = row; i < row + size_t(g.width); ++i) {
      b.layer[i] = layer_depth(g, i);
      b.weight[i] = minified_weight(g.mask_texels[i]);
      b.tone[i] = tone_weight(frame.rgb[i], exposure);
    }
  });
  each_row(g, [&](int, size_t row) {
    for (int u = 0; u < g.width; ++u) {
      const size_t i = row + size_t(u);
      b.row_near[i] = b.weight[i] > 0.0f || (u > 0 && b.weight[i - 1] > 0.0f) || (u + 1 < g.width && b.weight[i + 1] > 0.0f);
    }
  });
  scratch.resize(frame.width, frame.height);  // blended values of the pixels near a mask, then copied back
  each_row(g, [&](int v, size_t row) {
    for (int u = 0; u < g.width; ++u)
      if (near_mask(g, b, u, v)) scratch.rgb[row + size_t(u)] = blend_pixel(g, frame, b, u, v);
  });
  each_row(g, [&](int v, size_t row) {
    for (int u = 0; u < g.width; ++u)
      if (near_mask(g, b, u, v)) frame.rgb[row + size_t(u)] = scratch.rgb[row + size_t(u)];
  });
}

}  // namespace silva::render
