#pragma once
/// @file FCL collision proxies of placed objects: the asset's proxy shape scaled, turned by yaw
/// and moved to the object's ground contact point.
#include <fcl/common/types.h>
#include <fcl/geometry/collision_geometry.h>

#include <memory>

#include "assets/library.hpp"
#include "core/types.hpp"

namespace silva::world {

/// A proxy in world space ready for fcl::collide (geometry null for Shape::None).
struct PlacedProxy {
  std::shared_ptr<fcl::CollisionGeometryf> geometry;  ///< Scaled shape.
  fcl::Transform3f transform = fcl::Transform3f::Identity();  ///< Shape frame -> world.
};

/// Object-to-world transform [R|t] of an object at `position`, turned by yaw (radians) about +Z, scaled.
Affine3f object_to_world(const Vec3f& position, float yaw, float scale);

/// The proxy of an object placed at `position` with yaw and uniform scale.
PlacedProxy place_proxy(const assets::CollisionProxy& proxy, const Vec3f& position, float yaw, float scale);

/// FCL narrow-phase test of two placed proxies (false when either has no geometry).
bool proxies_collide(const PlacedProxy& a, const PlacedProxy& b);

}  // namespace silva::world
