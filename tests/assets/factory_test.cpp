// The generic factory test (Infinigen habit): every built-in factory, several seeds and variants.
#include "assets/factory.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <set>

#include "tests/common/mesh_checks.hpp"

namespace silva::assets {
namespace {

/// Plausible real-world size of each factory's assets: height range (m) of the full-detail bounds,
/// widest horizontal extent, trunk (proxy) diameter range and the most triangles of a variant.
struct SizeRange {
  float min_height, max_height, max_width, min_diameter = 0, max_diameter = 0;
  size_t max_triangles = 6000;
};
SizeRange expected_size(const Factory& f) {
  const std::string name = f.prefix;
  if (name == "spruce") return {0.8f, 34.0f, 16.0f, 0.03f, 0.8f, 12000};
  if (name == "pine") return {0.8f, 34.0f, 19.0f, 0.03f, 0.8f, 12000};
  if (name == "larch") return {0.8f, 33.0f, 16.0f, 0.03f, 0.8f, 12000};
  if (name == "beech") return {0.8f, 34.0f, 26.0f, 0.03f, 0.9f, 12000};
  if (name == "birch") return {0.8f, 27.0f, 18.0f, 0.03f, 0.6f, 12000};
  if (name == "oak") return {0.8f, 28.0f, 30.0f, 0.03f, 1.1f, 12000};
  if (name == "dead_tree") return {2.5f, 20.5f, 12.0f, 0.18f, 0.75f};
  if (name == "fallen_tree") return {0.2f, 4.0f, 15.0f};
  if (name == "wood_sorrel") return {0.03f, 0.16f, 0.8f, 0, 0, 320};
  if (name == "woodruff") return {0.06f, 0.32f, 1.0f, 0, 0, 400};
  if (name == "nettle") return {0.25f, 1.25f, 2.2f, 0, 0, 700};
  if (name == "wood_anemone") return {0.05f, 0.3f, 1.25f, 0, 0, 400};
  if (name == "grass_sward") return {0.03f, 0.2f, 1.0f, 0, 0, 260};
  switch (f.kind) {
    case AssetKind::Stump: return {0.3f, 0.95f, 1.8f, 0, 0, 3000};
    case AssetKind::Grass: return {0.05f, 0.85f, 1.0f, 0, 0, 64};
    case AssetKind::Fern: return {0.15f, 1.1f, 2.8f, 0, 0, 3000};
    case AssetKind::Shrub: return {0.15f, 5.5f, 6.0f, 0, 0, 3000};
    case AssetKind::Rock: return {0.05f, 1.5f, 1.5f, 0, 0, 3000};
    case AssetKind::Log: return {0.2f, 0.9f, 6.3f};
    case AssetKind::GroundCover: return {0.003f, 0.5f, 0.55f, 0, 0, 500};
    default: return {0, 0, 0};
  }
}

/// Roles a kind's parts may have.
std::set<Role> allowed_roles(AssetKind k) {
  switch (k) {
    case AssetKind::ConiferTree:
    case AssetKind::BroadleafTree: return {Role::TreeTrunk, Role::TreeCanopy};
    case AssetKind::DeadTree: return {Role::DeadTree};
    case AssetKind::Stump: return {Role::Stump};
    case AssetKind::Grass:
    case AssetKind::Fern: return {Role::GroundVegetation};
    case AssetKind::Shrub: return {Role::Shrub};
    case AssetKind::GroundCover: return {Role::Ground};
    default: return {Role::Obstacle};
  }
}

CollisionProxy::Shape expected_proxy(AssetKind k) {
  switch (k) {
    case AssetKind::Grass:
    case AssetKind::Fern:
    case AssetKind::GroundCover: return CollisionProxy::Shape::None;
    case AssetKind::Log: return CollisionProxy::Shape::Capsule;
    case AssetKind::Rock: return CollisionProxy::Shape::Box;  // or Sphere, checked below
    default: return CollisionProxy::Shape::Cylinder;
  }
}

bool same_bytes(const Mesh& a, const Mesh& b) {
  return a.positions.size() == b.positions.size() && a.indices == b.indices &&
         std::memcmp(a.positions.data(), b.positions.data(), a.positions.size() * sizeof(Vec3f)) == 0 &&
         std::memcmp(a.normals.data(), b.normals.data(), a.normals.size() * sizeof(Vec3f)) == 0 &&
         std::memcmp(a.uvs.data(), b.uvs.data(), a.uvs.size() * sizeof(Vec2f)) == 0;
}

void check_asset(const Factory& f, const Asset& a) {
  SCOPED_TRACE(a.name);
  // Card-only assets (grass, ferns, leaf litter) keep its one level (cards are never thinned); the others reduce.
  const auto& parts = a.lods()[0].parts;
  const bool card_only = std::all_of(parts.begin(), parts.end(), [](const MeshPart& p) { return p.mask != nullptr; });
  if (card_only) EXPECT_EQ(a.lods().size(), 1u);
  else ASSERT_GE(a.lods().size(), 2u);
  ASSERT_EQ(a.lod_screen_sizes.size(), a.lods().size() - 1);
  for (size_t k = 0; k < a.lods().size(); ++k) {
    test::expect_valid_mesh(a.lods()[k], "lod" + std::to_string(k));
    ASSERT_EQ(a.lods()[k].parts.size(), a.lods()[0].parts.size());
    for (size_t p = 0; p < a.lods()[k].parts.size(); ++p) EXPECT_EQ(a.lods()[k].parts[p].role, a.lods()[0].parts[p].role);
    if (k > 0) {
      EXPECT_LT(a.lods()[k].triangle_count(), a.lods()[k - 1].triangle_count());
      EXPECT_GT(a.lod_screen_sizes[k - 1], 0.0f);
      if (k > 1) {
        EXPECT_LT(a.lod_screen_sizes[k - 1], a.lod_screen_sizes[k - 2]);
      }
    }
  }
  const Mesh& m = a.lods()[0];
  const SizeRange size = expected_size(f);
  EXPECT_LE(m.triangle_count(), size.max_triangles);
  const std::set<Role> roles = allowed_roles(f.kind);
  for (const MeshPart& p : m.parts) EXPECT_TRUE(roles.count(p.role)) << role_name(p.role);
  EXPECT_TRUE(roles.count(a.role));
  // Sizes: height of the bounds above ground, horizontal extent, origin at the ground contact.
  const AABB box = m.bounds();
  EXPECT_GE(box.max.z(), size.min_height);
  EXPECT_LE(box.max.z(), size.max_height);
  EXPECT_LE(std::max(box.size().x(), box.size().y()), size.max_width);
  EXPECT_LE(box.min.z(), 0.01f);
  EXPECT_GE(box.min.z(), -0.25f * box.size().z());
  // Counter-clockwise fronts: each triangle's face normal agrees with its vertex normals.
  size_t disagree = 0, faces = 0;
  for (size_t t = 0; t < m.indices.size(); t += 3) {
    const Vec3f &p0 = m.positions[m.indices[t]], &p1 = m.positions[m.indices[t + 1]], &p2 = m.positions[m.indices[t + 2]];
    const Vec3f n = (p1 - p0).cross(p2 - p0);
    if (n.norm() < 1e-9f) continue;
    ++faces;
    const Vec3f vn = m.normals[m.indices[t]] + m.normals[m.indices[t + 1]] + m.normals[m.indices[t + 2]];
    disagree += n.dot(vn) <= 0;
  }
  EXPECT_EQ(disagree, 0u) << "of " << faces;
  // Collision proxy.
  if (f.kind == AssetKind::Rock) {
    EXPECT_TRUE(a.proxy.shape == CollisionProxy::Shape::Box || a.proxy.shape == CollisionProxy::Shape::Sphere);
  } else {
    EXPECT_EQ(a.proxy.shape, expected_proxy(f.kind));
  }
  if (size.max_diameter > 0) {
    EXPECT_GE(2 * a.proxy.radius, size.min_diameter);
    EXPECT_LE(2 * a.proxy.radius, size.max_diameter);
    EXPECT_LE(a.proxy.height, box.max.z());
  }
  if (f.kind == AssetKind::Log) {
    const float length = a.proxy.height + 2 * a.proxy.radius;
    EXPECT_GE(length, 0.8f * box.size().x());  // along the lying trunk
    EXPECT_LE(length, size.max_width + 0.5f);
    EXPECT_GE(length, 3.0f);
  }
  if (a.proxy.shape != CollisionProxy::Shape::None) {
    EXPECT_GT(a.proxy.footprint_radius(), 0.0f);
    EXPECT_LE(a.proxy.footprint_radius(), 0.75f * std::max(box.size().x(), box.size().y()));  // box: half diagonal
  }
}

TEST(Factory, EveryKindHasAFactoryWithSeveralVariantsInKindOrder) {
  std::set<AssetKind> kinds;
  std::set<std::string> prefixes;
  AssetKind last = AssetKind(0);
  for (const Factory& f : factories()) {
    kinds.insert(f.kind);
    EXPECT_TRUE(prefixes.insert(f.prefix).second) << f.prefix;
    EXPECT_GE(f.variants, 4u) << f.prefix;
    EXPECT_GE(f.kind, last) << f.prefix;
    last = f.kind;
    EXPECT_GT(expected_size(f).max_height, 0.0f) << f.prefix << " has no size expectation";
  }
  EXPECT_EQ(kinds.size(), size_t(AssetKind::Count));
}

TEST(Factory, FactoriesSharingAKindDrawIndependentStreams) {
  const Factory* previous = nullptr;
  for (const Factory& f : factories()) {
    if (previous && previous->kind == f.kind) {
      const Asset a = make_asset(*previous, 5, 0), b = make_asset(f, 5, 0);
      EXPECT_FALSE(same_bytes(a.lods()[0], b.lods()[0])) << previous->prefix << " " << f.prefix;
    }
    previous = &f;
  }
}

TEST(Factory, EveryFactoryMakesValidAssetsForSeveralSeeds) {
  for (const Factory& f : factories())
    for (uint64_t seed : {uint64_t(1), uint64_t(77), kDefaultAssetSeed})
      for (uint32_t v = 0; v < 3; ++v) check_asset(f, make_asset(f, seed, v));
}

TEST(Factory, SameSeedSameBytesDifferentSeedDifferentMesh) {
  for (const Factory& f : factories()) {
    SCOPED_TRACE(f.prefix);
    const Asset a = make_asset(f, 5, 1), b = make_asset(f, 5, 1);
    ASSERT_EQ(a.lods().size(), b.lods().size());
    for (size_t k = 0; k < a.lods().size(); ++k) EXPECT_TRUE(same_bytes(a.lods()[k], b.lods()[k]));
    EXPECT_FALSE(same_bytes(a.lods()[0], make_asset(f, 6, 1).lods()[0]));
    EXPECT_FALSE(same_bytes(a.lods()[0], make_asset(f, 5, 2).lods()[0]));
  }
}

TEST(Factory, AllVariantsOfAFactoryDiffer) {
  for (const Factory& f : factories()) {
    SCOPED_TRACE(f.prefix);
    std::vector<Mesh> meshes;
    for (uint32_t v = 0; v < f.variants; ++v) meshes.push_back(make_asset(f, 9, v).lods()[0]);
    for (size_t i = 0; i < meshes.size(); ++i)
      for (size_t j = i + 1; j < meshes.size(); ++j) EXPECT_FALSE(same_bytes(meshes[i], meshes[j])) << i << " " << j;
  }
}

TEST(Factory, FactoriesSharingAKindDrawDifferentShapes) {
  const auto all = factories();
  for (size_t i = 0; i + 1 < all.size(); ++i)
    if (all[i].kind == all[i + 1].kind) {
      EXPECT_STRNE(all[i].prefix, all[i + 1].prefix);
      EXPECT_FALSE(same_bytes(make_asset(all[i], 4, 0).lods()[0], make_asset(all[i + 1], 4, 0).lods()[0]));
    }
}

TEST(Factory, GenerateLibraryIndexesKindsAndNamesAreUnique) {
  const AssetLibrary lib = generate_library(3);
  std::set<std::string> names;
  size_t total = 0;
  for (const Factory& f : factories()) total += f.variants;
  ASSERT_EQ(lib.assets.size(), total);
  for (const Asset& a : lib.assets) EXPECT_TRUE(names.insert(a.name).second) << a.name;
  for (size_t k = 0; k < size_t(AssetKind::Count); ++k)
    for (uint32_t i : lib.by_kind[k]) EXPECT_EQ(size_t(lib.assets[i].kind), k);
  EXPECT_EQ(lib.assets[0].name, "spruce_00");
  EXPECT_EQ(lib.assets[0].file, "");  // procedural: no file
  ASSERT_TRUE(lib.assets[0].source.has_value());
  EXPECT_EQ(lib.assets[0].source->generator, "spruce");
  EXPECT_EQ(lib.assets[0].source->seed, 3u);
}

}  // namespace
}  // namespace silva::assets
