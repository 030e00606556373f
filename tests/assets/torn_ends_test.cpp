// Dead wood's broken-off branches: their tubes end in splintered broken_wood caps.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "assets/tree_mesh.hpp"

namespace silva::assets {
namespace {

/// A 5 m trunk (its top thick, but the trunk is never capped), a 0.6 m stub broken off at 4 cm radius
/// (6 tube sides), and a branch tapering below kMinTubeRadius (its tube ends at the minimum).
Skeleton stub_skeleton() {
  Skeleton s;
  s.branches.push_back({{{Vec3f(0, 0, 0), 0.2f}, {Vec3f(0, 0, 5), 0.1f}}, -1, 0, 5.0f, 0});
  s.branches.push_back({{{Vec3f(0, 0, 2), 0.05f}, {Vec3f(0.6f, 0, 2.1f), 0.04f}}, 0, 1, 0.61f, 0.4f});
  s.branches.push_back({{{Vec3f(0, 0, 3), 0.03f}, {Vec3f(0, 0.8f, 3.2f), 0.005f}}, 0, 1, 0.82f, 0.6f});
  return s;
}

Mesh mesh_of(bool torn_ends) {
  TreeLook look{Material::BarkDead, Role::DeadTree, false, {}};
  look.torn_ends = torn_ends;
  MeshBuilder b;
  Rng rng(5, 0, Purpose::AssetShape);
  mesh_tree(b, stub_skeleton(), look, rng);
  return b.finish();
}

/// Positions of the vertices the triangles of `part` use.
std::vector<Vec3f> part_positions(const Mesh& m, const MeshPart& part) {
  std::vector<Vec3f> out;
  for (uint32_t i = part.first_index; i < part.first_index + part.index_count; ++i) out.push_back(m.positions[m.indices[i]]);
  return out;
}

TEST(TornEnds, OnlyTheStubGetsASplinteredCapThatClosesItsTube) {
  for (const MeshPart& p : mesh_of(false).parts) EXPECT_NE(p.material, Material::BrokenWood);
  const Mesh m = mesh_of(true);
  const MeshPart* cap = nullptr;
  const MeshPart* bark = nullptr;
  for (const MeshPart& p : m.parts) {
    if (p.material == Material::BrokenWood) cap = &p;
    if (p.material == Material::BarkDead) bark = &p;
  }
  ASSERT_NE(cap, nullptr);
  ASSERT_NE(bark, nullptr);
  EXPECT_EQ(cap->role, Role::DeadTree);
  EXPECT_EQ(cap->index_count, 3u * 5u * 6u);  // one cap of 5 triangles per side of the 6-sided stub
  const Vec3f end(0.6f, 0, 2.1f), axis = (end - Vec3f(0, 0, 2)).normalized();
  const std::vector<Vec3f> tube = part_positions(m, *bark), splinters = part_positions(m, *cap);
  int rim = 0;
  for (const Vec3f& v : splinters) {
    EXPECT_GT((v - end).dot(axis), -1e-5f);          // out of the wood, never into it
    EXPECT_LT((v - end).dot(axis), 1.5f * 0.04f + 1e-4f);  // no farther than the jag allows
    EXPECT_LT((v - end).norm(), 0.04f * 2.0f);
    if (std::abs((v - end).norm() - 0.04f) < 1e-4f && std::abs((v - end).dot(axis)) < 1e-5f) {
      ++rim;  // the cap's rim is the tube's end ring, point for point: no crack between them
      EXPECT_NE(std::find(tube.begin(), tube.end(), v), tube.end());
    }
  }
  EXPECT_GE(rim, 6);
}

}  // namespace
}  // namespace silva::assets
