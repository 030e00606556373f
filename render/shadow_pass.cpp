#include "render/shadow_pass.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/error.hpp"
#include "render/raster_conventions.hpp"

namespace silva::render {

ShadowMap shadow_map_frame(const Vec3d& direction_to_sun, const AABB& region, int resolution) {
  const double len = direction_to_sun.norm();
  if (!(len > 0.0) || !std::isfinite(len))
    throw InputError("shadow map: direction_to_sun must be a finite non-zero vector");
  if (region.empty() || !region.min.allFinite() || !region.max.allFinite())
    throw InputError("shadow map: the region box is empty or not finite");
  if (resolution < 1 || resolution > kMaxRasterSize)
    throw InputError("shadow map: resolution " + std::to_string(resolution) + " is outside 1.." +
                     std::to_string(kMaxRasterSize));
  const Vec3d z = -direction_to_sun / len;
  const Vec3d h = std::abs(z.z()) > 0.99 ? Vec3d::UnitX() : Vec3d::UnitZ();
  const Vec3d x = h.cross(z).normalized();
  const Vec3d y = z.cross(x);
  ShadowMap map;
  map.world_to_light = Mat4d::Identity();
  map.world_to_light.block<1, 3>(0, 0) = x.transpose();
  map.world_to_light.block<1, 3>(1, 0) = y.transpose();
  map.world_to_light.block<1, 3>(2, 0) = z.transpose();
  double min_x = std::numeric_limits<double>::infinity(), max_x = -min_x, min_y = min_x, max_y = -min_x;
  for (int c = 0; c < 8; ++c) {
    const Vec3d p((c & 1) ? region.max.x() : region.min.x(), (c & 2) ? region.max.y() : region.min.y(),
                  (c & 4) ? region.max.z() : region.min.z());
    const double lx = x.dot(p), ly = y.dot(p);
    min_x = std::min(min_x, lx);
    max_x = std::max(max_x, lx);
    min_y = std::min(min_y, ly);
    max_y = std::max(max_y, ly);
  }
  // Square texels; the longer side of the footprint gets `resolution` of them.
  const double extent = std::max({max_x - min_x, max_y - min_y, 1e-6});
  map.texel_size = extent / double(resolution);
  const auto texels = [&](double side) { return std::clamp(int(std::ceil(side / map.texel_size - 1e-9)), 1, resolution); };
  map.width = texels(max_x - min_x);
  map.height = texels(max_y - min_y);
  map.origin_x = min_x;
  map.origin_y = min_y;
  return map;
}

ViewProjection shadow_view(const ShadowMap& map) {
  return ViewProjection::orthographic(map.world_to_light, map.origin_x, map.origin_y, map.texel_size, map.width,
                                      map.height);
}

void shadow_depth_from_visibility(const VisibilityBuffer& vis, ShadowMap& map) {
  map.depth.resize(vis.size());
  for (size_t i = 0; i < vis.size(); ++i)
    map.depth[i] = vis.instance[i] == kNoInstance ? std::numeric_limits<float>::infinity() : -vis.depth[i];
}

}  // namespace silva::render
