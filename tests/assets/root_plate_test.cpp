// The root plate of fallen trees (assets/root_plate.hpp): a lobed soil lens with a forest-floor front
// face, roots reaching past its rim, its buried part cut flat; known bounds over several seeds.
#include "assets/root_plate.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>

namespace silva::assets {
namespace {

constexpr float kRadius = 1.0f;

/// The plate of seed `seed` facing +x at x = 0, radius 1 m, on a 0.2 m trunk.
Mesh plate(uint64_t seed) {
  MeshBuilder b;
  Rng rng(seed, 1, Purpose::Test);
  add_root_plate(b, rng, {0.0f, kRadius, 0.2f});
  return b.finish();
}

/// Distance of p from the plate's axis (the x line through its centre, 0.55 radius up).
float off_axis(const Vec3f& p) { return Vec3f(0, p.y(), p.z() - 0.55f * kRadius).norm(); }

/// The vertices of the parts of `m` with material `material`.
std::vector<Vec3f> vertices_of(const Mesh& m, Material material) {
  std::vector<Vec3f> out;
  for (const MeshPart& part : m.parts)
    if (part.material == material)
      for (uint32_t i = part.first_index; i < part.first_index + part.index_count; ++i) out.push_back(m.positions[m.indices[i]]);
  return out;
}

TEST(RootPlate, IsALobedSoilLensWithAForestFloorFaceAndRootsPastItsRim) {
  for (uint64_t seed = 1; seed <= 12; ++seed) {
    SCOPED_TRACE(seed);
    const Mesh m = plate(seed);
    for (const MeshPart& part : m.parts) EXPECT_EQ(part.role, Role::Obstacle);
    std::vector<Vec3f> face = vertices_of(m, Material::Moss);
    if (face.empty()) face = vertices_of(m, Material::LeafLitter);
    ASSERT_FALSE(face.empty()) << "no moss or litter front face";
    // The front face's rim (its points away from the centre, above the cut) is lobed, not round.
    float lo = 1e9f, hi = 0;
    for (const Vec3f& p : face) {
      EXPECT_NEAR(p.x(), 0.0f, 0.3f * kRadius);
      const float r = off_axis(p);
      if (r < 0.6f * kRadius || p.z() < 0.0f) continue;  // the face's inner ring, or cut at the pit
      lo = std::min(lo, r);
      hi = std::max(hi, r);
    }
    EXPECT_GE(lo, 0.96f * kRootPlateMinLobe * kRadius - 1e-4f);
    EXPECT_LE(hi, kRootPlateMaxLobe * kRadius + 1e-4f);
    EXPECT_GT(hi / lo, 1.1f) << "a round disc";
    // Roots leave the soil: some soil vertex lies well beyond the widest point of the rim.
    const std::vector<Vec3f> soil = vertices_of(m, Material::Soil);
    float reach = 0;
    for (const Vec3f& p : soil) reach = std::max(reach, off_axis(p));
    EXPECT_GT(reach, 1.1f * hi);
    // The buried part is cut flat at 0.2 radius below the ground (roots lying on the cut reach a root's
    // thickness, at most 0.38 trunk radii, lower).
    for (const Vec3f& p : m.positions) ASSERT_GE(p.z(), -0.2f * kRadius - 0.38f * 0.2f - 1e-5f);
  }
}

TEST(RootPlate, IsAFunctionOfItsSeed) {
  const Mesh a = plate(5), b = plate(5), c = plate(6);
  ASSERT_EQ(a.positions.size(), b.positions.size());
  EXPECT_EQ(std::memcmp(a.positions.data(), b.positions.data(), a.positions.size() * sizeof(Vec3f)), 0);
  EXPECT_EQ(a.indices, b.indices);
  EXPECT_FALSE(a.positions.size() == c.positions.size() &&
               std::memcmp(a.positions.data(), c.positions.data(), a.positions.size() * sizeof(Vec3f)) == 0);
}

}  // namespace
}  // namespace silva::assets
