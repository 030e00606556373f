#include <gtest/gtest.h>

#include <cmath>

#include "render/bark_materials.hpp"
#include "render/materials.hpp"

namespace silva::render {
namespace {

/// A point on the side of a trunk of radius 0.25 m standing at (2, -3): angle a (radians) around
/// it, height z (m), height fraction `up` in the tree, seen with `footprint` metres per pixel.
SurfacePoint trunk_point(Material m, float a, float z, float up, float footprint) {
  const Vec3f outward(std::cos(a), std::sin(a), 0.0f);
  SurfacePoint s{Vec3f(2.0f, -3.0f, z) + outward * 0.25f, outward, Vec2f(0.5f, up), m, 1};
  s.footprint = footprint;
  return s;
}

/// Every furrowed species, low on the trunk (where pine and birch carry their plates).
constexpr Material kPlated[] = {Material::BarkSpruce, Material::BarkPine, Material::BarkLarch, Material::BarkOak,
                                Material::BarkBirch};

/// Mean albedo over a 1.5 m band of trunk sampled every 5 mm of arc and 1 cm of height.
Vec3d mean_albedo(Material m, float footprint) {
  Vec3d sum = Vec3d::Zero();
  int n = 0;
  for (int i = 0; i < 314; ++i)
    for (int k = 0; k < 150; ++k, ++n)
      sum += species_bark(trunk_point(m, 0.02f * float(i), 1.0f + 0.01f * float(k), 0.02f, footprint)).albedo.cast<double>();
  return sum / n;
}

TEST(ShadingBark, AFarTrunkKeepsTheMeanColourOfItsPlatesAndFissures) {
  for (const Material m : kPlated) {
    const Vec3d near = mean_albedo(m, 0.0f), far = mean_albedo(m, 1.0f);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(far[c] / near[c], 1.0, 0.02) << material_name(m) << " channel " << c;
  }
}

TEST(ShadingBark, PlatesShowDarkFissuresUpClose) {
  for (const Material m : kPlated) {
    int dark = 0, n = 0;
    double darkest = 1.0, lightest = 0.0;
    for (int i = 0; i < 300; ++i, ++n) {
      const float luma = species_bark(trunk_point(m, 0.021f * float(i), 1.0f + 0.013f * float(i), 0.02f, 0.0f)).albedo.sum();
      darkest = std::min(darkest, double(luma));
      lightest = std::max(lightest, double(luma));
      dark += luma < 0.5f * species_bark(trunk_point(m, 0.0f, 1.0f, 0.02f, 1.0f)).albedo.sum() ? 1 : 0;
    }
    EXPECT_LT(darkest, 0.5 * lightest) << material_name(m);
    EXPECT_GT(dark, n / 50) << material_name(m);  // fissures cover a few percent or more
    EXPECT_LT(dark, n / 2) << material_name(m);   // but plates most of the bark
  }
}

TEST(ShadingBark, FissureWallsTiltTheNormalUpCloseAndFadeFarAway) {
  for (const Material m : kPlated) {
    int steep = 0;
    for (int i = 0; i < 400; ++i) {
      const SurfacePoint s = trunk_point(m, 0.011f * float(i), 1.0f + 0.007f * float(i), 0.02f, 0.0005f);
      const Vec3f slope = species_bark(s).slope;
      EXPECT_LE(slope.norm(), kMaxBarkSlope * 1.0001f) << material_name(m);
      steep += slope.norm() > 0.3f ? 1 : 0;  // a wall of 17 degrees or more
      EXPECT_EQ(species_bark(trunk_point(m, 0.011f * float(i), 1.0f + 0.007f * float(i), 0.02f, 1.0f)).slope, Vec3f::Zero())
          << material_name(m);
    }
    EXPECT_GT(steep, 4) << material_name(m);
  }
  for (const Material smooth : {Material::BarkBeech, Material::Rock}) {
    const SurfacePoint s = trunk_point(smooth, 0.3f, 1.2f, 0.02f, 0.0005f);
    EXPECT_EQ(species_bark(s).slope, Vec3f::Zero()) << material_name(smooth);
  }
  // High on a pine (thin flaking bark) and on a birch's white bark there are no fissures.
  EXPECT_EQ(species_bark(trunk_point(Material::BarkPine, 0.3f, 12.0f, 0.9f, 0.0005f)).slope, Vec3f::Zero());
  EXPECT_EQ(species_bark(trunk_point(Material::BarkBirch, 0.3f, 12.0f, 0.9f, 0.0005f)).slope, Vec3f::Zero());
}

}  // namespace
}  // namespace silva::render
