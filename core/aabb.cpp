#include "core/aabb.hpp"

namespace silva {

AABB AABB::transformed(const Affine3f& m) const {
  AABB out;
  if (empty()) return out;
  for (int c = 0; c < 8; ++c) {
    const Vec3f p((c & 1) ? max.x() : min.x(), (c & 2) ? max.y() : min.y(), (c & 4) ? max.z() : min.z());
    out.extend(Vec3f(m.leftCols<3>() * p + m.col(3)));
  }
  return out;
}

}  // namespace silva
