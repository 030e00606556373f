#include "render/shadow_plan.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

#include "core/error.hpp"
#include "render/shadow_pass.hpp"

namespace silva::render {

int shadow_resolution(const Camera& camera) {
  const unsigned longer = unsigned(std::max(camera.width, camera.height));
  return std::clamp(int(std::bit_ceil(longer)), kMinShadowResolution, kShadowResolution);
}

AABB shadow_box(const Camera& camera, float ground_z, double max_elevation) {
  const Vec3d p = camera.position();
  const double half = 0.5 * kShadowExtent;
  const float relief = float(max_elevation) + 1.0f;
  AABB box;
  box.extend(Vec3f(float(p.x() - half), float(p.y() - half), ground_z - 2.0f * relief));
  box.extend(Vec3f(float(p.x() + half), float(p.y() + half), ground_z + 2.0f * relief + 40.0f));
  return box;
}

AABB fit_shadow_box(const AABB& box, const Camera& camera) {
  const Vec3d p = camera.position();
  // No point of the box is farther than its farthest corner, and a point's depth along the
  // optical axis never exceeds its distance: the frustum up to that depth holds every visible point.
  double reach = 0.0;
  for (int c = 0; c < 8; ++c) {
    const Vec3d corner((c & 1) ? box.max.x() : box.min.x(), (c & 2) ? box.max.y() : box.min.y(),
                       (c & 4) ? box.max.z() : box.min.z());
    reach = std::max(reach, (corner - p).norm());
  }
  // The truncated frustum is the convex hull of the camera centre and its far image corners.
  AABB frustum;
  frustum.extend(p.cast<float>());
  for (const auto& [u, v] : {std::pair{0, 0}, std::pair{camera.width, 0}, std::pair{0, camera.height},
                             std::pair{camera.width, camera.height}}) {
    const Vec3d ray = camera.camera_to_world.block<3, 3>(0, 0) *
                      Vec3d((double(u) - camera.cx) / camera.fx, (double(v) - camera.cy) / camera.fy, 1.0);
    frustum.extend((p + reach * ray).cast<float>());
  }
  AABB fitted = box;
  for (int a = 0; a < 2; ++a) {
    fitted.min[a] = std::max(box.min[a], frustum.min[a]);
    fitted.max[a] = std::min(box.max[a], frustum.max[a]);
  }
  return fitted;
}

ShadowPlan plan_shadow(std::span<const Camera> views, float ground_z, double max_elevation,
                       const Vec3d& direction_to_sun) {
  if (views.empty()) throw InputError("plan_shadow: no views");
  const AABB full = shadow_box(views.front(), ground_z, max_elevation);
  const int full_resolution = shadow_resolution(views.front());
  ShadowPlan plan;
  for (const Camera& view : views) {
    const AABB fitted = fit_shadow_box(full, view);
    if (!fitted.empty()) plan.region.extend(fitted);
  }
  if (plan.region.empty()) {  // the camera sees nothing of the box: keep a minimal map
    plan.region = full;
    plan.resolution = std::min(kMinShadowResolution, full_resolution);
    return plan;
  }
  // Same texel size as the full box's map: texels = full texels x (fitted footprint / full footprint).
  const double full_texel = shadow_map_frame(direction_to_sun, full, full_resolution).texel_size;
  const double fitted_extent = shadow_map_frame(direction_to_sun, plan.region, 1).texel_size;
  plan.resolution = std::clamp(int(std::ceil(fitted_extent / full_texel - 1e-9)),
                               std::min(kMinShadowResolution, full_resolution), full_resolution);
  return plan;
}

}  // namespace silva::render
