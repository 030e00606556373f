#include "render/edge_aa.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <vector>

#include "render/edge_aa_lanes.hpp"

namespace silva::render {

namespace {

/// Luma of an RGB byte triple (Rec. 601-like integer weights, exact in float).
float luma(const uint8_t* p) { return (2.0f * float(p[0]) + 5.0f * float(p[1]) + float(p[2])) * 0.125f; }

/// Blends the pixel at `c` towards the pixel at `other` by `blend` into `dst`, rounding half up.
void blend_pixel(const uint8_t* c, const uint8_t* other, float blend, uint8_t* dst) {
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
  const size_t padding = edge_lane_padding();
  // Byte offset of each EdgeNeighbour from the pixel (index 0 unused).
  const std::ptrdiff_t offset[5] = {0, -std::ptrdiff_t(stride), std::ptrdiff_t(stride), 3, -3};
  tbb::parallel_for(tbb::blocked_range<int>(0, height, 16), [&](const tbb::blocked_range<int>& range) {
    // Luma of three consecutive rows, rolled down the range (each row's luma computed once), padded
    // for the lanes' loads past the row's end.
    // Sized once: the padding stays zero, each row's fill writes only its lumas.
    std::vector<float> ring[3];
    for (std::vector<float>& l : ring) l.assign(size_t(width) + padding + 1, 0.0f);
    const auto fill = [&](std::vector<float>& l, int y) {
      const uint8_t* row = rgb.data() + size_t(std::clamp(y, 0, height - 1)) * stride;
      for (int x = 0; x < width; ++x) l[size_t(x)] = luma(row + size_t(x) * 3);
    };
    std::vector<int32_t> columns(size_t(width) + padding), neighbours(size_t(width) + padding);
    std::vector<float> blends(size_t(width) + padding);
    fill(ring[0], range.begin() - 1);
    fill(ring[1], range.begin());
    for (int y = range.begin(); y != range.end(); ++y) {
      fill(ring[(y - range.begin() + 2) % 3], y + 1);
      const uint8_t* row = rgb.data() + size_t(y) * stride;
      uint8_t* dst = out.data() + size_t(y) * stride;
      // Border pixels and pixels off an edge are copied.
      std::copy(row, row + stride, dst);
      if (y == 0 || y == height - 1 || width < 3) continue;
      const size_t count = edge_blends_lanes(ring[(y - range.begin()) % 3].data(), ring[(y - range.begin() + 1) % 3].data(),
                                             ring[(y - range.begin() + 2) % 3].data(), 1, width - 1,
                                             {columns.data(), blends.data(), neighbours.data()});
      for (size_t k = 0; k < count; ++k) {
        const size_t at = size_t(columns[k]) * 3;
        blend_pixel(row + at, row + at + offset[neighbours[k]], blends[k], dst + at);
      }
    }
  });
}

}  // namespace silva::render
