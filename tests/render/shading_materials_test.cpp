#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "highway_targets.hpp"
#include "render/floor_litter.hpp"
#include "render/materials.hpp"
#include "core/value_noise.hpp"
#include "core/surface_overlay.hpp"

namespace silva::render {
namespace {

SurfacePoint point(Material m, const Vec3f& p = Vec3f(3.2f, -1.7f, 0.4f), uint32_t variation = 1) {
  return {p, Vec3f(0, 0, 1), Vec2f(0.5f, 0.5f), m, variation};
}

TEST(ShadingMaterials, EveryMaterialIsAPlausibleDeterministicAlbedo) {
  for (int m = 0; m < int(Material::Count); ++m) {
    for (int k = 0; k < 50; ++k) {
      const SurfacePoint s = point(Material(m), Vec3f(0.37f * float(k), -0.61f * float(k), 0.05f * float(k)));
      const Vec3f a = material_albedo(s);
      EXPECT_TRUE(a.allFinite());
      EXPECT_GT(a.minCoeff(), 0.0f) << material_name(Material(m));
      // Natural surfaces are darker than 60 %; white petals reflect up to about 80 %.
      EXPECT_LT(a.maxCoeff(), Material(m) == Material::Petals ? 0.85f : 0.6f) << material_name(Material(m));
      EXPECT_EQ(a, material_albedo(s));
    }
  }
}

TEST(ShadingMaterials, SpringLeavesAreLighterAndYellowerThanSummersAndPetalsWhite) {
  for (Material summer : {Material::LeavesBeech, Material::LeavesOak, Material::NeedlesLarch}) {
    const Vec3f young = material_albedo(point(Material::SpringLeaves)), old = material_albedo(point(summer));
    EXPECT_GT(young.y(), old.y()) << material_name(summer);
    EXPECT_GT(young.x() / young.y(), old.x() / old.y()) << material_name(summer);
    EXPECT_GT(young.y(), young.x());
  }
  const Vec3f petal = material_albedo(point(Material::Petals));
  EXPECT_GT(petal.minCoeff(), 0.85f * petal.maxCoeff());  // white, not tinted
  EXPECT_GT(petal.minCoeff(), 0.4f);
  EXPECT_GT(material_response(Material::SpringLeaves).translucency, 0.5f);
}

TEST(ShadingMaterials, MattedBrackenIsDarkerAndRedderThanStandingDeadBracken) {
  for (uint32_t variation = 1; variation <= 8; ++variation) {  // the same spot and plant, by plant
    const Vec3f matted = material_albedo(point(Material::MattedBracken, Vec3f(1, 2, 0.1f), variation));
    const Vec3f standing = material_albedo(point(Material::DeadBracken, Vec3f(1, 2, 0.1f), variation));
    EXPECT_LT(matted.sum(), 0.8f * standing.sum());
    EXPECT_GT(matted.x() / matted.z(), 1.5f * standing.x() / standing.z());  // rust, not grey-brown
    EXPECT_GT(matted.x(), matted.y());
  }
}

TEST(ShadingMaterials, FoliageIsGreenAndVariesPerInstance) {
  for (Material m : {Material::Needles, Material::Leaves, Material::Fern, Material::ShrubLeaves}) {
    const Vec3f a = material_albedo(point(m, Vec3f(1, 2, 3), 1));
    const Vec3f b = material_albedo(point(m, Vec3f(1, 2, 3), 2));
    EXPECT_GT(a.y(), a.x()) << material_name(m);
    EXPECT_GT(a.y(), a.z()) << material_name(m);
    EXPECT_NE(a, b) << material_name(m);
    EXPECT_GT(material_response(m).translucency, 0.5f);
  }
  EXPECT_EQ(material_response(Material::BarkConifer).translucency, 0.0f);
  EXPECT_EQ(material_response(Material::Ground).translucency, 0.0f);
}

TEST(ShadingMaterials, BarkVariesAcrossTheTrunkMoreThanAlongIt) {
  // Vertical streaks: moving 5 cm around the trunk changes the colour more than moving 5 cm up.
  double across = 0, along = 0;
  for (int k = 0; k < 200; ++k) {
    const Vec3f p(0.3f + 0.013f * float(k), 0.2f, 1.0f + 0.021f * float(k));
    const Vec3f a = material_albedo(point(Material::BarkConifer, p));
    across += (material_albedo(point(Material::BarkConifer, p + Vec3f(0.05f, 0, 0))) - a).norm();
    along += (material_albedo(point(Material::BarkConifer, p + Vec3f(0, 0, 0.05f))) - a).norm();
  }
  EXPECT_GT(across, 1.5 * along);
}

TEST(ShadingMaterials, TrailFadesIntoTheGroundByItsEdgeCoordinate) {
  // uv.x is the signed distance to the trail's edge: inside it is trail, by the margin it is ground.
  float centre_gap = 0.0f;
  for (int k = 0; k < 16; ++k) {
    const Vec3f p(4.0f + 0.37f * float(k), 1.0f - 0.21f * float(k), 0.0f);
    SurfacePoint centre = point(Material::Trail, p), margin = point(Material::Trail, p);
    centre.uv.x() = -0.6f;
    margin.uv.x() = kOverlayMargin + kOverlayRagged;
    const Vec3f ground = material_albedo(point(Material::Ground, p));
    centre_gap += (material_albedo(centre) - ground).norm() / 16.0f;
    EXPECT_EQ(material_albedo(margin), ground);
  }
  EXPECT_GT(centre_gap, 3e-2f);
}

}  // namespace
}  // namespace silva::render

namespace silva::render {
namespace {

/// The ground formula of materials.hpp from the scalar noise functions and floor_litter.hpp's scalar
/// sprites (test oracle); returns the albedo and sets `soil_weight`.
Vec3f ground_oracle(const Vec3f& p, const Vec3f& n, float footprint, float& soil_weight, float needle_share = -1.0f,
                    float spruce = 0.0f) {
  const auto smoothstep = [](float e0, float e1, float x) {
    return smooth_weight(std::clamp((x - e0) / (e1 - e0), 0.0f, 1.0f));
  };
  const float flat = smoothstep(0.6f, 0.9f, n.z());
  const float fine_detail = 1.0f - smoothstep(0.01f, 0.05f, footprint);
  const float sprites = litter_fade(footprint);
  const float needles = needle_share >= 0.0f ? needle_share
                                             : smoothstep(0.42f, 0.58f, fbm2(p.x() * 0.02f, p.y() * 0.02f, 2, kGroundStandSalt));
  const float leaf = value_noise2(p.x() * 9.0f, p.y() * 9.0f, kGroundLeafSalt);
  const float dry = smoothstep(0.6f, 0.8f, leaf) * (1.0f - needles) * (fine_detail * (1.0f - sprites));
  const float grass = smoothstep(0.62f, 0.78f, fbm2(p.x() * 0.06f, p.y() * 0.06f, 2, kGroundGrassSalt)) * 0.8f * flat;
  const float moss = smoothstep(0.6f, 0.72f, fbm2(p.x() * 0.15f, p.y() * 0.15f, 3, kGroundMossSalt)) * 0.85f * flat;
  const float soil =
      std::max(1.0f - flat, smoothstep(0.7f, 0.84f, fbm2(p.x() * 0.5f, p.y() * 0.5f, 3, kGroundSoilSalt)));
  const float grain = fbm2(p.x() * 4.0f, p.y() * 4.0f, 2, kGroundFineSalt);
  const float speckle = value_noise2(p.x() * 23.0f, p.y() * 23.0f, kGroundLeafSalt + 1);
  const float brightness = (1.0f + (grain * 0.6f - 0.3f) * (1.0f - smoothstep(0.1f, 0.4f, footprint))) *
                           (1.0f + (speckle * 0.8f - 0.4f) * fine_detail);
  const float moss_shown = (1.0f - smoothstep(kMossDetailNear, kMossDetailFar, footprint)) * moss;
  float moss_tone = 1.0f;
  if (moss_shown > 0.0f) {
    const float cushion = value_noise2(p.x() * 40.0f, p.y() * 40.0f, kGroundCushionSalt);
    const float tips = value_noise2(p.x() * 110.0f, p.y() * 110.0f, kGroundCushionSalt + 1);
    moss_tone = 1.0f + ((cushion * 0.7f + tips * 0.3f) - 0.5f) * 0.9f * moss_shown;
  }
  Vec3f c;
  for (int k = 0; k < 3; ++k) {
    float v = mix(kGroundLeafLitter[k], kGroundNeedleLitter[k], needles);
    v = mix(v, kGroundDryLeaves[k], dry);
    v = mix(v, kGroundGrass[k], grass);
    v = mix(v, kGroundMoss[k] * moss_tone, moss);
    v = mix(v, kGroundSoil[k], soil);
    c[k] = v * brightness;
  }
  soil_weight = soil;
  Vec2f slope(0.0f, 0.0f);  // the sprites' tilt: not checked here
  litter_sprites(p.x(), p.y(), footprint, {grass * (1.0f / 0.8f), needles, 0.0f}, sprites * (1.0f - moss * 0.7f) * (1.0f - soil), c, slope);
  if (spruce > 0.0f)
    spruce_cones(p.x(), p.y(), footprint, needles * spruce, spruce_cone_fade(footprint) * (1.0f - moss * 0.7f) * (1.0f - soil), c,
                 slope);
  return c;
}

TEST(ShadingMaterials, GroundRowsAreTheFormulaBitForBitOnEveryHighwayTarget) {
  std::vector<Vec3f> p, n;
  std::vector<float> footprint;
  for (int i = 0; i < 45; ++i) {  // odd count: full vectors plus a tail
    p.emplace_back(float(i) * 3.7f - 60.0f, float(i * i % 37) * 1.3f - 20.0f, float(i % 5));
    n.push_back(Vec3f(0.1f * float(i % 9), 0.0f, 1.0f - 0.02f * float(i % 13)).normalized());
    footprint.push_back(0.011f * float(i % 41));  // 0 .. 0.44 m: every detail fade
  }
  float moss_x = 0.0f;  // a moss carpet: the first point of a line where the moss noise is high
  while (fbm2(moss_x * 0.15f, 5.0f * 0.15f, 3, kGroundMossSalt) < 0.75f) moss_x += 1.3f;
  for (int i = 0; i < 101; ++i) {  // its cushions up close
    p.emplace_back(moss_x + 0.0017f * float(i), 5.0f + 0.0011f * float(i % 13), 0.0f);
    n.emplace_back(0.0f, 0.0f, 1.0f);
    footprint.push_back(0.0002f * float(i));  // 0 .. 2 cm: the cushions in full to faded
  }
  for (int i = 0; i < 403; ++i) {  // near the camera, where the litter sprites lie: 1.3 mm apart
    p.emplace_back(12.3f + 0.0013f * float(i), -7.1f + 0.0009f * float(i % 97), 0.2f);
    n.emplace_back(0.0f, 0.0f, 1.0f);
    footprint.push_back(0.00005f * float(i % 450));  // 0 .. 2 cm: full sprites to faded
  }
  for (int i = 0; i < 1024; ++i) {  // a square metre 3.1 cm apart, sharp: about ten points on cones where needles lie
    p.emplace_back(-3.0f + 0.031f * float(i % 32), 4.0f + 0.031f * float(i / 32), 0.1f);
    n.emplace_back(0.0f, 0.0f, 1.0f);
    footprint.push_back(0.0005f);
  }
  for (int i = 0; i < 512; ++i) {  // 2 m x 1 m 6.1 cm apart, footprints 0 .. 6 cm: spruce cones in full to faded
    p.emplace_back(7.0f + 0.061f * float(i % 32), -1.0f + 0.061f * float(i / 32), 0.0f);
    n.emplace_back(0.0f, 0.0f, 1.0f);
    footprint.push_back(0.00012f * float(i % 500));
  }
  const std::vector<int64_t> targets = test::highway_targets();
  ASSERT_GE(targets.size(), 2u);
  for (int64_t target : targets) {
    const test::PinnedTarget pinned(target);
    ASSERT_EQ(ground_simd_target(), target);
    SCOPED_TRACE(hwy::TargetName(target));
    std::vector<Vec3f> out(p.size());
    std::vector<float> soil(p.size());
    ground_albedo_row(p.data(), n.data(), footprint.data(), p.size(), out.data(), soil.data());
    for (const float share : {0.0f, 0.85f, 1.0f})  // a forest type's litter everywhere, with and without spruce cones
      for (const float spruce : {0.0f, 0.5f, 1.0f}) {
        std::vector<Vec3f> typed(p.size());
        ground_albedo_row(p.data(), n.data(), footprint.data(), p.size(), typed.data(), nullptr, nullptr,
                          FloorLook{0.0f, share, spruce});
        for (size_t i = 0; i < p.size(); ++i) {
          float soil_weight = -1.0f;
          EXPECT_EQ(typed[i], ground_oracle(p[i], n[i], footprint[i], soil_weight, share, spruce)) << share << " " << i;
        }
      }
    for (size_t i = 0; i < p.size(); ++i) {
      float soil_weight = -1.0f;
      EXPECT_EQ(out[i], ground_oracle(p[i], n[i], footprint[i], soil_weight)) << i;
      EXPECT_EQ(soil[i], soil_weight) << i;
      float unused = 0.0f;
      SurfacePoint s{p[i], n[i], Vec2f::Zero(), Material::Ground, 0};
      EXPECT_EQ(material_albedo(s), ground_oracle(p[i], n[i], 0.0f, unused)) << i;
    }
  }
}

TEST(ShadingMaterials, FoliageRowsAreMaterialAlbedoBitForBitOnEveryHighwayTarget) {
  const Material kinds[] = {Material::Needles, Material::LeavesBirch, Material::NeedlesSpruce, Material::DeadBracken};
  std::vector<Vec3f> p, base;
  std::vector<uint32_t> variation;
  std::vector<float> leaf;
  std::vector<Vec3f> want;
  for (int i = 0; i < 53; ++i) {  // odd count: full vectors plus a tail; negative coordinates floor downwards
    const Material m = kinds[i % 4];
    p.emplace_back(float(i) * 0.37f - 9.0f, float(i * i % 41) * 0.21f - 4.0f, float(i % 7) * 1.9f - 3.0f);
    variation.push_back(uint32_t(i) * 2654435761u);
    Vec3f b;
    ASSERT_TRUE(plain_foliage_base(m, b));
    base.push_back(b);
    leaf.push_back(leaf_brightness(uint8_t(100 + i * 3)));  // below, across and above the per-leaf alphas
    want.push_back(material_albedo(SurfacePoint{p.back(), Vec3f::UnitZ(), Vec2f::Zero(), m, variation.back(), FloorLook{},
                                                leaf.back()}));
  }
  for (int64_t target : test::highway_targets()) {
    const test::PinnedTarget pinned(target);
    SCOPED_TRACE(hwy::TargetName(target));
    std::vector<Vec3f> out(p.size());
    foliage_albedo_row(p.data(), variation.data(), base.data(), leaf.data(), p.size(), out.data());
    for (size_t i = 0; i < p.size(); ++i) EXPECT_EQ(out[i], want[i]) << i;
  }
}

TEST(ShadingMaterials, PlainFoliageIsItsBaseTintedAndMottled) {
  Vec3f base;
  ASSERT_TRUE(plain_foliage_base(Material::NeedlesSpruce, base));
  EXPECT_FALSE(plain_foliage_base(Material::Grass, base));  // grass adds patches and tips
  EXPECT_FALSE(plain_foliage_base(Material::Ground, base));
  ASSERT_TRUE(plain_foliage_base(Material::LeavesBirch, base));
  const SurfacePoint s{Vec3f(1.5f, -2.25f, 7.0f), Vec3f::UnitZ(), Vec2f::Zero(), Material::LeavesBirch, 12345};
  const Vec3f q = s.position * kFoliageMottleScale;
  EXPECT_EQ(material_albedo(s),
            foliage_albedo(base, s.variation, value_noise3(q.x(), q.y(), q.z(), kFoliageMottleSalt), 1.0f));
  EXPECT_NE(foliage_albedo(base, 1, 0.5f, 1.0f), foliage_albedo(base, 2, 0.5f, 1.0f));  // tinted per instance
  EXPECT_GT(foliage_albedo(base, 1, 1.0f, 1.0f).sum(), foliage_albedo(base, 1, 0.0f, 1.0f).sum());
  EXPECT_EQ(foliage_albedo(base, 1, 0.5f, 1.25f), foliage_albedo(base, 1, 0.5f, 1.0f) * 1.25f);  // a brighter leaf
}

TEST(ShadingMaterials, LeafBrightnessComesFromTheMaskAlpha) {
  EXPECT_EQ(leaf_brightness(0), 1.0f);
  EXPECT_EQ(leaf_brightness(127), 1.0f);
  EXPECT_EQ(leaf_brightness(255), 1.0f);  // binary masks keep their look
  EXPECT_EQ(leaf_brightness(128), 0.75f);
  EXPECT_EQ(leaf_brightness(254), 1.25f);
  EXPECT_FLOAT_EQ(leaf_brightness(191), 1.0f);
}

}  // namespace
}  // namespace silva::render
