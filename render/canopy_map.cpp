#include "render/canopy_map.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace silva::render {

namespace {

/// Lowest sine of the light's elevation used to turn light-space depth into height (a grazing light
/// would make metres of height thousands of metres of depth).
constexpr double kMinSunSine = 0.1;

/// Raw (unblurred) cover and cover x depth of one cell of `b` x `b` shadow texels.
struct CellCanopy {
  float cover = 0, cover_depth = 0;
};

/// The canopy of cell (cx, cy): the ground's light-space depth under the cell's farthest surface
/// (one refinement along the light), then the texels at least kCanopyHeight above it.
CellCanopy cell_canopy(const ShadowMap& s, const Mat4d& light_to_world, double sun_sine, const GroundHeight& ground,
                       int b, int cx, int cy) {
  const int x0 = cx * b, y0 = cy * b, x1 = std::min(x0 + b, s.width), y1 = std::min(y0 + b, s.height);
  float far = -std::numeric_limits<float>::infinity();
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      const float d = s.depth[size_t(y) * size_t(s.width) + size_t(x)];
      if (std::isfinite(d)) far = std::max(far, d);
    }
  if (!std::isfinite(far)) return {};
  const double lx = s.origin_x + (0.5 * double(x0 + x1)) * s.texel_size;
  const double ly = s.origin_y + (0.5 * double(y0 + y1)) * s.texel_size;
  double ground_depth = double(far);
  for (int step = 0; step < 2; ++step) {
    const Eigen::Vector4d w = light_to_world * Eigen::Vector4d(lx, ly, ground_depth, 1.0);
    ground_depth += (w.z() - ground(w.x(), w.y())) / sun_sine;
  }
  const float limit = float(ground_depth - kCanopyHeight / sun_sine);
  int count = 0;
  double depth_sum = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      const float d = s.depth[size_t(y) * size_t(s.width) + size_t(x)];
      if (d <= limit) ++count, depth_sum += double(d);
    }
  const float share = float(count) / float((x1 - x0) * (y1 - y0));
  return {share, count > 0 ? float(depth_sum / double(count)) * share : 0.0f};
}

/// Box means of radius r along rows (step 1) or columns (step width) of a width x height plane, in place;
/// beyond the plane counts as no canopy.
void box_blur(std::vector<float>& plane, int width, int height, int r, bool columns) {
  const int lines = columns ? width : height, length = columns ? height : width;
  const size_t step = columns ? size_t(width) : 1, line_step = columns ? 1 : size_t(width);
  tbb::parallel_for(tbb::blocked_range<int>(0, lines), [&](const tbb::blocked_range<int>& range) {
    std::vector<float> line(static_cast<size_t>(length));
    for (int l = range.begin(); l < range.end(); ++l) {
      float* p = plane.data() + size_t(l) * line_step;
      for (int i = 0; i < length; ++i) line[size_t(i)] = p[size_t(i) * step];
      // A running sum over the window [i - r, i + r]: one add and one subtract per texel at any radius.
      double sum = 0;
      for (int k = 0; k < std::min(r, length); ++k) sum += double(line[size_t(k)]);
      for (int i = 0; i < length; ++i) {
        const int enter = i + r, leave = i - r - 1;
        if (enter < length) sum += double(line[size_t(enter)]);
        if (leave >= 0) sum -= double(line[size_t(leave)]);
        p[size_t(i) * step] = float(sum / double(2 * r + 1));
      }
    }
  });
}

}  // namespace

AABB canopy_region(const AABB& shaded) {
  AABB region = shaded;
  if (region.empty()) return region;
  for (int a = 0; a < 2; ++a) {
    region.min[a] -= float(kCanopyStandRadius);
    region.max[a] += float(kCanopyStandRadius);
  }
  return region;
}

CanopyMap build_canopy_map(const ShadowMap& shadow, const GroundHeight& ground) {
  CanopyMap map;
  if (shadow.width <= 0 || shadow.height <= 0 || !(shadow.texel_size > 0.0)) return map;
  const int b = std::max(1, int(std::lround(kCanopyCell / shadow.texel_size)));
  map.width = (shadow.width + b - 1) / b;
  map.height = (shadow.height + b - 1) / b;
  map.world_to_light = shadow.world_to_light;
  map.cell = double(b) * shadow.texel_size;
  map.origin_x = shadow.origin_x;
  map.origin_y = shadow.origin_y;
  const Mat4d light_to_world = shadow.world_to_light.inverse();
  const double sun_sine = std::max(-shadow.world_to_light(2, 2), kMinSunSine);
  const size_t cells = size_t(map.width) * size_t(map.height);
  map.cover.assign(cells, 0.0f);
  map.depth.assign(cells, 0.0f);
  tbb::parallel_for(tbb::blocked_range<int>(0, map.height), [&](const tbb::blocked_range<int>& rows) {
    for (int cy = rows.begin(); cy < rows.end(); ++cy)
      for (int cx = 0; cx < map.width; ++cx) {
        const CellCanopy c = cell_canopy(shadow, light_to_world, sun_sine, ground, b, cx, cy);
        const size_t i = size_t(cy) * size_t(map.width) + size_t(cx);
        map.cover[i] = c.cover;
        map.depth[i] = c.cover_depth;
      }
  });
  std::vector<float> stand_cover = map.cover, stand_depth = map.depth;
  const int r = std::max(1, int(std::lround(kCanopyRadius / map.cell)));
  const int stand_r = std::max(1, int(std::lround(kCanopyStandRadius / map.cell)));
  for (bool columns : {false, true})
    for (auto [plane, radius] : {std::pair{&map.cover, r}, std::pair{&map.depth, r}, std::pair{&stand_cover, stand_r},
                                 std::pair{&stand_depth, stand_r}})
      box_blur(*plane, map.width, map.height, radius, columns);
  for (size_t i = 0; i < cells; ++i) {
    const float near = map.cover[i], stand = kCanopyStandWeight * stand_cover[i];
    const float weight = near + stand;
    map.depth[i] = weight > 0.0f ? (map.depth[i] + kCanopyStandWeight * stand_depth[i]) / weight : 0.0f;
    map.cover[i] = 1.0f - (1.0f - near) * (1.0f - stand);
  }
  return map;
}

}  // namespace silva::render
