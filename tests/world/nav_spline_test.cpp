#include "world/nav_spline.hpp"

#include <gtest/gtest.h>

namespace silva::world {

TEST(NavSpline, StraightLineKnownAnswers) {
  const NavSpline s({Vec3d(0, 0, 0), Vec3d(3, 4, 0), Vec3d(3, 4, 2)});
  EXPECT_DOUBLE_EQ(s.length(), 7.0);
  EXPECT_TRUE(s.position(2.5).isApprox(Vec3d(1.5, 2.0, 0)));
  EXPECT_TRUE(s.position(6.0).isApprox(Vec3d(3, 4, 1)));
  EXPECT_TRUE(s.position(-1).isApprox(Vec3d(0, 0, 0)));
  EXPECT_TRUE(s.position(99).isApprox(Vec3d(3, 4, 2)));
  EXPECT_TRUE(s.tangent(1.0).isApprox(Vec3d(0.6, 0.8, 0)));
  EXPECT_TRUE(s.tangent(6.5).isApprox(Vec3d(0, 0, 1)));
}

TEST(NavSpline, CatmullRomInterpolatesControlPoints) {
  const std::vector<Eigen::Vector2d> c = {{0, 0}, {10, 0}, {15, 8}, {30, 8}};
  const auto pts = catmull_rom_centripetal(c, 50);
  ASSERT_EQ(pts.size(), size_t(3 * 50 + 1));
  for (size_t k = 0; k < c.size(); ++k) EXPECT_LT((pts[k * 50] - c[k]).norm(), 1e-9) << k;
  // Smooth: consecutive samples are close.
  for (size_t k = 1; k < pts.size(); ++k) EXPECT_LT((pts[k] - pts[k - 1]).norm(), 1.0);
}

}  // namespace silva::world
