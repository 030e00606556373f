#include "render/depth_of_field.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace silva::render {

namespace {

constexpr int kTile = 16;     // tile side of the largest-circle map (at least kMaxCocRadius)
constexpr int kSamples = 64;  // gather points: the centre plus a golden-angle spiral

/// Unit-disc offsets of the gather: the centre, then kSamples - 1 points of a golden-angle spiral.
const std::array<Vec2f, kSamples>& disc() {
  static const std::array<Vec2f, kSamples> points = [] {
    std::array<Vec2f, kSamples> p{};
    const double golden = 3.14159265358979323846 * (3.0 - std::sqrt(5.0));
    for (int k = 1; k < kSamples; ++k) {
      const double r = std::sqrt((double(k) - 0.5) / double(kSamples - 1)), a = golden * double(k);
      p[size_t(k)] = Vec2f(float(r * std::cos(a)), float(r * std::sin(a)));
    }
    return p;
  }();
  return points;
}

/// Per-pixel circle-of-confusion radii (capped) and, per tile, the largest radius of it and its 8 neighbours.
struct CocMap {
  std::vector<float> radius, tile_max;  ///< Per pixel; per tile (its 3x3 tiles' largest).
  int tiles_x = 0, tiles_y = 0;         ///< Tiles across and down.

  /// Evaluates the radii of every pixel of `depth`, then the tile maxima.
  CocMap(const std::vector<float>& depth, const Camera& camera, const DepthOfField& dof)
      : radius(depth.size()),
        tiles_x((camera.width + kTile - 1) / kTile),
        tiles_y((camera.height + kTile - 1) / kTile) {
    for (size_t i = 0; i < depth.size(); ++i)
      radius[i] = std::min(0.5f * coc_diameter_px(dof, camera, depth[i]), kMaxCocRadius);
    std::vector<float> own(size_t(tiles_x) * size_t(tiles_y), 0.0f);
    for (int v = 0; v < camera.height; ++v)
      for (int u = 0; u < camera.width; ++u) {
        float& m = own[size_t(v / kTile) * size_t(tiles_x) + size_t(u / kTile)];
        m = std::max(m, radius[size_t(v) * size_t(camera.width) + size_t(u)]);
      }
    tile_max.assign(own.size(), 0.0f);
    for (int ty = 0; ty < tiles_y; ++ty)
      for (int tx = 0; tx < tiles_x; ++tx) {
        float m = 0.0f;
        for (int y = std::max(ty - 1, 0); y <= std::min(ty + 1, tiles_y - 1); ++y)
          for (int x = std::max(tx - 1, 0); x <= std::min(tx + 1, tiles_x - 1); ++x)
            m = std::max(m, own[size_t(y) * size_t(tiles_x) + size_t(x)]);
        tile_max[size_t(ty) * size_t(tiles_x) + size_t(tx)] = m;
      }
  }
};

}  // namespace

float coc_diameter_px(const DepthOfField& dof, const Camera& camera, float z) {
  const double f = dof.focal_length_mm * 1e-3, s = dof.focus_distance;
  const double scale = camera.fx * f / (dof.f_number * (s - f));
  if (z <= 0.0f) return float(scale);  // sky: the limit for z -> infinity
  return float(scale * std::abs(double(z) - s) / double(z));
}

void apply_depth_of_field(const LinearFrame& in, const std::vector<float>& depth, const Camera& camera,
                          const DepthOfField& dof, LinearFrame& out) {
  out.resize(in.width, in.height);
  const CocMap coc(depth, camera, dof);
  const auto& points = disc();
  const float far = std::numeric_limits<float>::infinity();
  tbb::parallel_for(tbb::blocked_range<int>(0, in.height), [&](const tbb::blocked_range<int>& rows) {
    for (int v = rows.begin(); v < rows.end(); ++v)
      for (int u = 0; u < in.width; ++u) {
        const size_t i = size_t(v) * size_t(in.width) + size_t(u);
        const float reach = coc.tile_max[size_t(v / kTile) * size_t(coc.tiles_x) + size_t(u / kTile)];
        if (reach < 0.5f) {
          out.rgb[i] = in.rgb[i];
          continue;
        }
        const float z = depth[i] > 0.0f ? depth[i] : far, r = coc.radius[i];
        Vec3f sum = Vec3f::Zero();
        float weight = 0.0f;
        for (size_t k = 0; k < points.size(); ++k) {
          const int du = int(std::lround(points[k].x() * reach)), dv = int(std::lround(points[k].y() * reach));
          if (k > 0 && du == 0 && dv == 0) continue;  // the centre counts once
          const int qu = std::clamp(u + du, 0, in.width - 1), qv = std::clamp(v + dv, 0, in.height - 1);
          const size_t q = size_t(qv) * size_t(in.width) + size_t(qu);
          const float d = std::sqrt(float(du * du + dv * dv)), rq = coc.radius[q];
          const float zq = depth[q] > 0.0f ? depth[q] : far;
          if (d > rq + 0.5f || (zq > z && d > r + 0.5f)) continue;
          const float w = 1.0f / std::max(rq * rq, 1.0f);
          sum += in.rgb[q] * w;
          weight += w;
        }
        out.rgb[i] = sum / weight;  // the centre always counts: d = 0
      }
  });
}

}  // namespace silva::render
