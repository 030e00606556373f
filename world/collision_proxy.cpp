#include "world/collision_proxy.hpp"

// FCL's header-only narrow-phase templates, instantiated here for float, trip GCC 12's
// -Wmaybe-uninitialized inside /usr/include/fcl; the warning is not about this file's code.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"

#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/capsule.h>
#include <fcl/geometry/shape/cylinder.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/narrowphase/collision.h>

namespace silva::world {

using Shape = assets::CollisionProxy::Shape;

Affine3f object_to_world(const Vec3f& position, float yaw, float scale) {
  Affine3f m;
  m.leftCols<3>() = Eigen::AngleAxisf(yaw, Vec3f::UnitZ()).toRotationMatrix() * scale;
  m.col(3) = position;
  return m;
}

PlacedProxy place_proxy(const assets::CollisionProxy& proxy, const Vec3f& position, float yaw, float scale) {
  PlacedProxy p;
  const Mat3f turn = Eigen::AngleAxisf(yaw, Vec3f::UnitZ()).toRotationMatrix();
  Mat3f shape_rotation = turn;
  switch (proxy.shape) {
    case Shape::None:
      return p;
    case Shape::Cylinder:
    case Shape::Capsule: {
      const Vec3f axis = proxy.axis.norm() > 0 ? Vec3f(proxy.axis.normalized()) : Vec3f::UnitZ();
      shape_rotation = turn * Eigen::Quaternionf::FromTwoVectors(Vec3f::UnitZ(), axis).toRotationMatrix();
      if (proxy.shape == Shape::Cylinder)
        p.geometry = std::make_shared<fcl::Cylinderf>(proxy.radius * scale, proxy.height * scale);
      else
        p.geometry = std::make_shared<fcl::Capsulef>(proxy.radius * scale, proxy.height * scale);
      break;
    }
    case Shape::Box:
      p.geometry = std::make_shared<fcl::Boxf>(Vec3f(2.0f * scale * proxy.half_extents));
      break;
    case Shape::Sphere:
      p.geometry = std::make_shared<fcl::Spheref>(proxy.radius * scale);
      break;
  }
  p.transform.linear() = shape_rotation;
  p.transform.translation() = position + turn * (scale * proxy.center);
  return p;
}

bool proxies_collide(const PlacedProxy& a, const PlacedProxy& b) {
  if (!a.geometry || !b.geometry) return false;
  fcl::CollisionRequestf request;
  fcl::CollisionResultf result;
  return fcl::collide(a.geometry.get(), a.transform, b.geometry.get(), b.transform, request, result) > 0;
}

}  // namespace silva::world
