// Spring's young plants: ferns unrolling from croziers and nettle shoots, drawn from the same plants as summer's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "assets/factory.hpp"

namespace silva::assets {
namespace {

/// Variant `v` of the built-in generator `prefix` for `season`.
Mesh variant(const char* prefix, uint32_t v, Season season) {
  const Factory* f = find_factory(prefix);
  EXPECT_NE(f, nullptr) << prefix;
  return generate_variant(*f, kDefaultAssetSeed, v, season).mesh;
}

/// The centre lines of `count` strips or tubes laid one after another from vertex `start`: each node a run of
/// `ring` vertices (a strip's two edges; a tube's sides and seam), its centre the mean of the first `ring_points`.
std::vector<std::vector<Vec3f>> centre_lines(const Mesh& m, size_t start, size_t count, size_t nodes, size_t ring,
                                             size_t ring_points) {
  std::vector<std::vector<Vec3f>> out(count);
  for (size_t c = 0; c < count; ++c)
    for (size_t i = 0; i < nodes; ++i) {
      Vec3f sum = Vec3f::Zero();
      for (size_t k = 0; k < ring_points; ++k) sum += m.positions[start + (c * nodes + i) * ring + k];
      out[c].push_back(sum / float(ring_points));
    }
  return out;
}

/// The length of a polyline.
float length(const std::vector<Vec3f>& line) {
  float sum = 0;
  for (size_t i = 1; i < line.size(); ++i) sum += (line[i] - line[i - 1]).norm();
  return sum;
}

/// The angle (radians) a spine's direction turns through from its first segment to its last.
float turning(const std::vector<Vec3f>& spine) {
  float sum = 0;
  for (size_t i = 2; i < spine.size(); ++i) {
    const Vec3f a = (spine[i - 1] - spine[i - 2]).normalized(), b = (spine[i] - spine[i - 1]).normalized();
    sum += std::acos(std::clamp(a.dot(b), -1.0f, 1.0f));
  }
  return sum;
}

/// The highest point of a mesh.
float top(const Mesh& m) {
  float z = 0;
  for (const Vec3f& p : m.positions) z = std::max(z, p.z());
  return z;
}

TEST(YoungPlants, SpringFernsUnrollFromCroziers) {
  constexpr float kPi = std::numbers::pi_v<float>;
  constexpr size_t kBladeNodes = kYoungFrondSegments + 1, kCoilNodes = kCrozierSegments + 1, kRing = kCrozierSides + 1;
  for (uint32_t v = 0; v < 8; ++v) {
    const Mesh summer = variant("fern", v, Season::Summer), spring = variant("fern", v, Season::Spring);
    const size_t fronds = summer.positions.size() / (2 * (kFrondSegments + 1));
    ASSERT_EQ(summer.positions.size(), fronds * 2 * (kFrondSegments + 1));
    // The same plant, as many fronds: each a blade strip, then each frond's crozier, a tube.
    ASSERT_EQ(spring.positions.size(), fronds * (2 * kBladeNodes + kCoilNodes * kRing)) << v;
    ASSERT_EQ(spring.parts.size(), 2u);
    EXPECT_TRUE(spring.parts[0].mask);
    EXPECT_FALSE(spring.parts[1].mask);  // a solid coil
    for (const MeshPart& p : spring.parts) EXPECT_EQ(p.material, Material::SpringLeaves);
    const auto grown = centre_lines(summer, 0, fronds, kFrondSegments + 1, 2, 2);
    const auto blades = centre_lines(spring, 0, fronds, kBladeNodes, 2, 2);
    const auto coils = centre_lines(spring, fronds * 2 * kBladeNodes, fronds, kCoilNodes, kRing, kCrozierSides);
    for (size_t k = 0; k < fronds; ++k) {
      EXPECT_LT(turning(grown[k]), kPi) << v;  // a grown frond arches less than half a turn
      EXPECT_GT(turning(coils[k]), kPi) << v;  // a crozier rolls more than half a turn
      EXPECT_LT((coils[k].front() - blades[k].back()).norm(), 1e-5f) << v;  // atop its blade
      Vec3f lo = coils[k].front(), hi = lo;
      for (const Vec3f& p : coils[k]) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
      EXPECT_LE((hi - lo).maxCoeff(), 2.0f * kCrozierRadius[1] + 1e-4f) << v;
      EXPECT_GE((hi - lo).maxCoeff(), kCrozierRadius[0]) << v;
      EXPECT_LE(length(blades[k]), kYoungFrondOpen[1] * length(grown[k]) + 1e-4f) << v;  // mostly still rolled up
      EXPECT_GT(blades[k].back().z() - blades[k].front().z(), 0.8f * length(blades[k])) << v;  // standing steeply
    }
  }
}

TEST(YoungPlants, SpringNettlesAreShortShootsOfTheSamePatch) {
  for (uint32_t v = 0; v < 8; ++v) {
    const Mesh summer = variant("nettle", v, Season::Summer), spring = variant("nettle", v, Season::Spring);
    EXPECT_GT(top(spring), 0.08f) << v;
    EXPECT_LT(top(spring), 0.35f + 0.05f) << v;  // the tallest shoot with its top leaves
    EXPECT_LT(top(spring), 0.6f * top(summer)) << v;
    for (const MeshPart& p : spring.parts) EXPECT_EQ(p.material, Material::Fern);
  }
}

}  // namespace
}  // namespace silva::assets
