#include "assets/mesh_builder.hpp"

#include <gtest/gtest.h>

#include "tests/common/mesh_checks.hpp"

namespace silva::assets {
namespace {

/// Signed volume of a closed mesh (positive when front faces point outwards).
float signed_volume(const Mesh& m) {
  double v = 0;
  for (size_t t = 0; t < m.indices.size(); t += 3)
    v += m.positions[m.indices[t]].dot(m.positions[m.indices[t + 1]].cross(m.positions[m.indices[t + 2]]));
  return float(v / 6.0);
}

TEST(MeshBuilder, CardFacesRightCrossUpWithTopLeftUv) {
  MeshBuilder b;
  b.begin_part(Role::TreeCanopy, Material::Leaves, nullptr, true);
  add_card(b, Vec3f(0, 0, 1), Vec3f(0.5f, 0, 0), Vec3f(0, 0, 0.5f));
  const Mesh m = b.finish();
  test::expect_valid_mesh(m, "card");
  ASSERT_EQ(m.triangle_count(), 2u);
  const Vec3f front = Vec3f::UnitX().cross(Vec3f::UnitZ());  // -Y
  for (size_t t = 0; t < 6; t += 3) {
    const Vec3f n = (m.positions[m.indices[t + 1]] - m.positions[m.indices[t]])
                        .cross(m.positions[m.indices[t + 2]] - m.positions[m.indices[t]]);
    EXPECT_GT(n.normalized().dot(front), 0.999f);
  }
  EXPECT_EQ(m.positions[0], Vec3f(-0.5f, 0, 1.5f));  // top-left
  EXPECT_EQ(m.uvs[0], Vec2f(0, 0));
  EXPECT_EQ(m.parts.size(), 1u);
  EXPECT_TRUE(m.parts[0].double_sided);
}

TEST(MeshBuilder, TubeRingsLieOnTheirRadiusAndCloseOutwards) {
  MeshBuilder b;
  b.begin_part(Role::TreeTrunk, Material::BarkConifer);
  const TubeNode nodes[] = {{Vec3f(0, 0, 0), 1.0f}, {Vec3f(0, 0, 2), 1.0f}};
  add_tube(b, nodes, 8);
  add_disc(b, Vec3f(0, 0, 2), Vec3f::UnitZ(), 1.0f, 8);
  add_disc(b, Vec3f(0, 0, 0), -Vec3f::UnitZ(), 1.0f, 8);
  const Mesh m = b.finish();
  test::expect_valid_mesh(m, "tube");
  EXPECT_EQ(m.triangle_count(), 8u * 2 + 8 + 8);
  for (size_t v = 0; v < 18; ++v) EXPECT_NEAR(m.positions[v].head<2>().norm(), 1.0f, 1e-5f);
  EXPECT_NEAR(signed_volume(m), 2.0f * std::sqrt(2.0f) * 2.0f, 1e-4f);  // octagon area 2 sqrt(2) r^2, height 2
}

TEST(MeshBuilder, LobedTubeRisesInRidgesAndItsNormalsFaceOut) {
  // A vertical tube of radius 1 from z = 0 to 1 with 5 ridges of height 0.5 at its foot, none at its top.
  const TubeLobes lobes{5, 0.3f};
  const TubeNode nodes[] = {{Vec3f(0, 0, 0), 1.0f, 0.5f}, {Vec3f(0, 0, 1), 1.0f, 0.0f}};
  MeshBuilder b;
  b.begin_part(Role::TreeTrunk, Material::BarkBeech);
  add_tube(b, nodes, 40, 0.0f, lobes);
  const Mesh m = b.finish();
  test::expect_valid_mesh(m, "lobed tube");
  float foot_lo = 9, foot_hi = 0;
  for (const Vec3f& p : m.positions) {
    const float r = Vec2f(p.x(), p.y()).norm();
    if (p.z() > 0.5f) {
      EXPECT_NEAR(r, 1.0f, 1e-5f);  // the top ring is round
      continue;
    }
    foot_lo = std::min(foot_lo, r);
    foot_hi = std::max(foot_hi, r);
  }
  EXPECT_NEAR(foot_lo, 1.0f, 1e-5f);  // the valleys keep the radius
  EXPECT_GT(foot_hi, 1.45f);          // ridges reach about 1.5
  EXPECT_LE(foot_hi, 1.5f + 1e-5f);
  EXPECT_FLOAT_EQ(lobes.ridge(0.3f), 1.0f);  // a ridge at the phase, a valley between two ridges
  EXPECT_FLOAT_EQ(lobes.ridge(0.3f + 3.14159265f / 5.0f), 0.0f);
  // Every vertex normal agrees with the faces it belongs to.
  for (size_t t = 0; t < m.indices.size(); t += 3) {
    const Vec3f &p0 = m.positions[m.indices[t]], &p1 = m.positions[m.indices[t + 1]], &p2 = m.positions[m.indices[t + 2]];
    const Vec3f face = (p1 - p0).cross(p2 - p0);
    for (int c = 0; c < 3; ++c) EXPECT_GT(face.dot(m.normals[m.indices[t + size_t(c)]]), 0.0f) << "triangle " << t / 3;
  }
  // Without lobes the tube is exactly the round one.
  const TubeNode round[] = {{Vec3f(0, 0, 0), 1.0f}, {Vec3f(0, 0, 1), 1.0f}};
  MeshBuilder plain, lobeless;
  plain.begin_part(Role::TreeTrunk, Material::BarkBeech);
  lobeless.begin_part(Role::TreeTrunk, Material::BarkBeech);
  add_tube(plain, round, 12);
  add_tube(lobeless, round, 12, 0.0f, lobes);
  EXPECT_EQ(plain.finish().positions, lobeless.finish().positions);
}

TEST(MeshBuilder, EmptyPartsAreDropped) {
  MeshBuilder b;
  b.begin_part(Role::Stump, Material::Wood);
  b.begin_part(Role::Stump, Material::BarkDead);
  add_disc(b, Vec3f::Zero(), Vec3f::UnitZ(), 1.0f, 5);
  const Mesh m = b.finish();
  ASSERT_EQ(m.parts.size(), 1u);
  EXPECT_EQ(m.parts[0].material, Material::BarkDead);
}

TEST(MeshBuilder, IcosphereCountsAndOrientation) {
  const Mesh m = unit_icosphere(1);
  EXPECT_EQ(m.positions.size(), 42u);
  EXPECT_EQ(m.triangle_count(), 80u);
  for (const Vec3f& p : m.positions) EXPECT_NEAR(p.norm(), 1.0f, 1e-6f);
  EXPECT_GT(signed_volume(m), 3.0f);  // close to 4/3 pi, positive = outward fronts
  EXPECT_LT(signed_volume(m), 4.19f);
  EXPECT_EQ(unit_icosphere(2).triangle_count(), 320u);
}

TEST(MeshBuilder, PerpendicularFrameIsRightHanded) {
  for (const Vec3f& axis : {Vec3f(0, 0, 1), Vec3f(1, 0, 0), Vec3f(0.3f, -0.5f, 0.8f).normalized()}) {
    Vec3f u, v;
    perpendicular_frame(axis, u, v);
    EXPECT_NEAR(u.dot(axis), 0.0f, 1e-6f);
    EXPECT_NEAR(v.dot(axis), 0.0f, 1e-6f);
    EXPECT_NEAR(u.norm(), 1.0f, 1e-6f);
    EXPECT_GT(u.cross(v).dot(axis), 0.9999f);
  }
}

}  // namespace
}  // namespace silva::assets
