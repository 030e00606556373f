#include "render/edge_aa.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace silva::render {

namespace {

/// Contrast (luma units 0..255) below which a pixel is left alone: absolute floor and relative share.
constexpr float kMinContrast = 8.0f;
constexpr float kRelativeContrast = 0.125f;
/// Largest blend towards the neighbour across the edge.
constexpr float kMaxBlend = 0.375f;

/// Luma of an RGB byte triple (Rec. 601-like integer weights, exact in float).
float luma(const uint8_t* p) { return (2.0f * float(p[0]) + 5.0f * float(p[1]) + float(p[2])) * 0.125f; }

/// Lumas of the rows above, at and below the pixel being filtered.
struct LumaRows {
  const float* up;
  const float* mid;
  const float* down;
};

/// Luma range of the pixel at x of the middle row and its four neighbours: max, and max - min.
struct Contrast {
  float hi, range;
};

/// The 3x3 cross's luma range at x (rows: luma() of the rows above, at and below).
Contrast contrast_at(const LumaRows& rows, int x) {
  const float lc = rows.mid[x], ln = rows.up[x], ls = rows.down[x], le = rows.mid[x + 1], lw = rows.mid[x - 1];
  const float hi = std::max({lc, ln, ls, le, lw}), lo = std::min({lc, ln, ls, le, lw});
  return {hi, hi - lo};
}

/// True when the pixel at x stands out enough from its cross to be filtered.
bool on_edge(const Contrast& c) { return !(c.range < std::max(kMinContrast, kRelativeContrast * c.hi)); }

/// Blends the interior edge pixel at (x, y) (on_edge) into `dst`; `rows` hold luma() of rows
/// y - 1, y, y + 1.
void filter_pixel(const uint8_t* src, const LumaRows& rows, int width, int x, int y, uint8_t* dst) {
  const size_t stride = size_t(width) * 3;
  const uint8_t* c = src + size_t(y) * stride + size_t(x) * 3;
  const uint8_t *n = c - stride, *s = c + stride, *e = c + 3, *w = c - 3;
  const float* l = rows.mid + x;
  const float* ln_row = rows.up + x;
  const float* ls_row = rows.down + x;
  const float lc = l[0], ln = ln_row[0], ls = ls_row[0], le = l[1], lw = l[-1];
  const float contrast = contrast_at(rows, x).range;
  const float lne = ln_row[1], lnw = ln_row[-1], lse = ls_row[1], lsw = ls_row[-1];
  // Luma change across rows (a horizontal edge) vs across columns (a vertical edge).
  const float across_rows = 2.0f * std::abs(ln + ls - 2.0f * lc) + std::abs(lne + lse - 2.0f * le) +
                            std::abs(lnw + lsw - 2.0f * lw);
  const float across_cols = 2.0f * std::abs(le + lw - 2.0f * lc) + std::abs(lne + lnw - 2.0f * ln) +
                            std::abs(lse + lsw - 2.0f * ls);
  // Blend towards the neighbour across the edge that differs most (all four on a tie, e.g. a spike).
  const uint8_t* other = c;
  float best = -1.0f;
  const auto consider = [&](const uint8_t* p, float l) {
    if (std::abs(l - lc) > best) best = std::abs(l - lc), other = p;
  };
  if (across_rows >= across_cols) consider(n, ln), consider(s, ls);
  if (across_cols >= across_rows) consider(e, le), consider(w, lw);
  // How much the pixel stands out from its neighbourhood, eased: 0 on smooth gradients, 1 on a spike.
  const float average = (2.0f * (ln + ls + le + lw) + lne + lnw + lse + lsw) / 12.0f;
  const float t = std::min(std::abs(average - lc) / contrast, 1.0f);
  const float eased = t * t * (3.0f - 2.0f * t);
  const float blend = kMaxBlend * eased;
  for (int k = 0; k < 3; ++k) {
    const float v = float(c[k]) + blend * (float(other[k]) - float(c[k]));
    dst[k] = uint8_t(int(v + 0.5f));  // NOLINT(bugprone-incorrect-roundings): v >= 0, round half up
  }
}

}  // namespace

void smooth_edges(const std::vector<uint8_t>& rgb, int width, int height, std::vector<uint8_t>& out) {
  if (width < 0 || height < 0 || rgb.size() != size_t(width) * size_t(height) * 3)
    throw std::invalid_argument("smooth_edges: image buffer does not match its size");
  out.resize(rgb.size());
  const size_t stride = size_t(width) * 3;
  tbb::parallel_for(tbb::blocked_range<int>(0, height, 16), [&](const tbb::blocked_range<int>& range) {
    // Luma of three consecutive rows, rolled down the range (each row's luma computed once).
    std::vector<float> ring[3];
    std::vector<int> edges(size_t(std::max(width, 0)));  // columns of the row's edge pixels
    const auto fill = [&](std::vector<float>& l, int y) {
      l.resize(size_t(width));
      const uint8_t* row = rgb.data() + size_t(std::clamp(y, 0, height - 1)) * stride;
      for (int x = 0; x < width; ++x) l[size_t(x)] = luma(row + size_t(x) * 3);
    };
    fill(ring[0], range.begin() - 1);
    fill(ring[1], range.begin());
    for (int y = range.begin(); y != range.end(); ++y) {
      fill(ring[(y - range.begin() + 2) % 3], y + 1);
      const LumaRows rows{ring[(y - range.begin()) % 3].data(), ring[(y - range.begin() + 1) % 3].data(),
                          ring[(y - range.begin() + 2) % 3].data()};
      const uint8_t* row = rgb.data() + size_t(y) * stride;
      uint8_t* dst = out.data() + size_t(y) * stride;
      if (y == 0 || y == height - 1 || width < 3) {
        std::copy(row, row + stride, dst);
        continue;
      }
      // Copy the row, then filter its edge pixels, listed without a branch per pixel (which pixels
      // are edges is as good as random in foliage).
      std::copy(row, row + stride, dst);
      size_t count = 0;
      for (int x = 1; x + 1 < width; ++x) {
        edges[count] = x;
        count += on_edge(contrast_at(rows, x)) ? 1 : 0;
      }
      for (size_t k = 0; k < count; ++k) filter_pixel(rgb.data(), rows, width, edges[k], y, dst + size_t(edges[k]) * 3);
    }
  });
}

}  // namespace silva::render
