#pragma once
/// @file Where a view's sun shadow map goes: the box of surfaces it must cover (the camera-centred
/// box cut to the view frustum) and its texel count (texel size fixed by the image size).
#include <span>

#include "core/aabb.hpp"
#include "core/camera.hpp"

namespace silva::render {

/// Side of the square region around the camera whose casters the sun shadow map covers (metres).
inline constexpr double kShadowExtent = 120.0;
/// Largest shadow map resolution (texels per side of the full kShadowExtent box).
inline constexpr int kShadowResolution = 2048;
/// Smallest shadow map resolution, for thumbnails and tests.
inline constexpr int kMinShadowResolution = 256;

/// Texels per side of the full kShadowExtent box for a view: the power of two at or above the
/// image's longer side, within [kMinShadowResolution, kShadowResolution], so shadow detail
/// follows image detail.
int shadow_resolution(const Camera& camera);

/// The camera-centred box of side kShadowExtent whose z band (ground - 2 relief to ground +
/// 2 relief + 40 m, relief = max_elevation + 1 m) holds the ground and every tree top.
AABB shadow_box(const Camera& camera, float ground_z, double max_elevation);

/// `box` with x and y cut to the bounds of the camera's view frustum up to the farthest corner of
/// `box` (z band kept): every point the camera can see inside `box` is inside the result.
AABB fit_shadow_box(const AABB& box, const Camera& camera);

/// Region and size of one view's shadow map.
struct ShadowPlan {
  AABB region;         ///< World box whose surfaces the map covers (fit_shadow_box of shadow_box).
  int resolution = 0;  ///< Texels per side: the full box's texel size kept, never more texels.
};

/// The shadow map of views taken from one position (the first view's; a fan of yaws, or one view) lit from
/// `direction_to_sun`: its region the union of each view's fit_shadow_box of the shadow_box around them, its
/// texels the size of the whole box's. `ground_z` is the terrain height under the cameras and
/// `max_elevation` the terrain's largest height above zero. Throws InputError for no views.
ShadowPlan plan_shadow(std::span<const Camera> views, float ground_z, double max_elevation,
                       const Vec3d& direction_to_sun);

}  // namespace silva::render
