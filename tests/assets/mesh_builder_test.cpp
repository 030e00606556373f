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
