#include "render/foliage_aa.hpp"

#include <algorithm>
#include <limits>

#include "render/foliage_aa_lanes.hpp"

namespace silva::render {

namespace {

/// Weight of radiance `c` in a blend at `exposure`: 1 / (1 + exposed luminance).
float tone_weight(const Vec3f& c, float exposure) {
  return 1.0f / (1.0f + exposure * (0.2126f * c.x() + 0.7152f * c.y() + 0.0722f * c.z()));
}

/// Running sum of one pixel's blend: the centre pixel's layer depth dp and blend weight wp, and the weighted sums.
struct PixelBlend {
  float dp, wp;
  Vec3f sum;
  float total;

  /// Adds neighbour x of row r with tent weight `tent`.
  void add(const BlendRowPlanes& r, size_t x, float tent) {
    const float dq = r.layer[x];
    const float behind = dq < std::numeric_limits<float>::infinity() && dq >= dp * (1.0f - kLayerTolerance) ? wp : 0.0f;
    const float in_front = dq <= dp * (1.0f + kLayerTolerance) ? r.weight[x] : 0.0f;
    const float w = tent * std::max(behind, in_front) * r.tone[x];
    sum += Eigen::Map<const Vec3f>(r.rgb + 3 * x) * w;
    total += w;
  }
};

}  // namespace

float minified_weight(float mask_texels) {
  return std::clamp((mask_texels - kMinifiedStart) / (kMinifiedFull - kMinifiedStart), 0.0f, 1.0f);
}

bool has_minified_masks(const GBuffer& g) {
  return std::any_of(g.mask_texels.begin(), g.mask_texels.end(), [](float m) { return m > kMinifiedStart; });
}

MaskBlendRows::MaskBlendRows(const GBuffer& g, float exposure, const LinearFrame& frame)
    : g_(g), frame_(frame), exposure_(exposure) {}

const MaskBlendRows::RowPlanes& MaskBlendRows::planes(int v) {
  RowPlanes& p = ring_[size_t(v) % ring_.size()];
  if (p.row == v) return p;
  const size_t w = size_t(g_.width), first = size_t(v) * w;
  p.row = v;
  p.layer.resize(w);
  p.weight.resize(w);
  p.tone.resize(w);
  p.near.resize(w);
  for (size_t u = 0; u < w; ++u) {
    const float depth = g_.depth[first + u];
    p.layer[u] = depth > 0.0f ? depth : std::numeric_limits<float>::infinity();
    p.weight[u] = minified_weight(g_.mask_texels[first + u]);
    p.tone[u] = tone_weight(frame_.rgb[first + u], exposure_);
  }
  for (size_t u = 0; u < w; ++u)
    p.near[u] = p.weight[u] > 0.0f || (u > 0 && p.weight[u - 1] > 0.0f) || (u + 1 < w && p.weight[u + 1] > 0.0f);
  return p;
}

void MaskBlendRows::blend(int v, Vec3f* out) {
  const size_t w = size_t(g_.width);
  const Vec3f* rgb = &frame_.rgb[size_t(v) * w];
  const RowPlanes& centre = planes(v);
  const RowPlanes* above = v > 0 ? &planes(v - 1) : nullptr;
  const RowPlanes* below = v + 1 < g_.height ? &planes(v + 1) : nullptr;
  const auto row_of = [&](const RowPlanes* p, int dy) {
    return p ? BlendRowPlanes{(rgb + std::ptrdiff_t(dy) * std::ptrdiff_t(w))->data(), p->layer.data(), p->weight.data(),
                              p->tone.data(), p->near.data()}
             : BlendRowPlanes{};
  };
  const std::array<BlendRowPlanes, 3> rows{row_of(above, -1), row_of(&centre, 0), row_of(below, 1)};
  size_t lanes_from = w, lanes_to = w;  // columns the SIMD lanes blend: whole vectors inside the frame
  if (above && below && w > 2) {
    lanes_from = 1;
    lanes_to = size_t(blend_inside_lanes(rows.data(), 1, int(w) - 1, out[1].data()));
  }
  for (size_t u = 0; u < w; ++u) {
    if (u == lanes_from) u = lanes_to;  // lanes_to < w: the last column is always blended here
    const bool near = centre.near[u] != 0 || (above && above->near[u] != 0) || (below && below->near[u] != 0);
    if (!near) {
      out[u] = rgb[u];
      continue;
    }
    const float tone = centre.tone[u];
    PixelBlend b{centre.layer[u], centre.weight[u], rgb[u] * (4.0f * tone), 4.0f * tone};
    if (above && below && u > 0 && u + 1 < w) {  // inside: no bounds per neighbour
      b.add(rows[0], u, 2.0f);
      b.add(rows[1], u - 1, 2.0f);
      b.add(rows[1], u + 1, 2.0f);
      b.add(rows[2], u, 2.0f);
      b.add(rows[0], u - 1, 1.0f);
      b.add(rows[0], u + 1, 1.0f);
      b.add(rows[2], u - 1, 1.0f);
      b.add(rows[2], u + 1, 1.0f);
    } else {
      for (size_t r = 0; r < 3; ++r)  // rows above, at and below; columns left, at and right
        for (size_t c = 0; c < 3; ++c) {
          const bool inside_row = (r == 0 && above) || r == 1 || (r == 2 && below);
          if ((r == 1 && c == 1) || !inside_row || (c == 0 && u == 0) || (c == 2 && u + 1 == w)) continue;
          b.add(rows[r], u + c - 1, (r == 1 || c == 1) ? 2.0f : 1.0f);
        }
    }
    out[u] = b.sum / b.total;
  }
}

}  // namespace silva::render
