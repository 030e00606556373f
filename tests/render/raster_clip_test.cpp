// Polygon clipping: kept parts, vertex counts and bit-identical crossings on shared edges.
#include <gtest/gtest.h>

#include "render/clip.hpp"

namespace silva::render {
namespace {

TEST(RasterClip, TriangleCrossingAPlaneKeepsItsInsidePart) {
  const Vec4d near(0, 0, 1, -1);  // z >= 1
  Vec3d poly[kMaxClippedVertices] = {Vec3d(0, 0, 0), Vec3d(4, 0, 4), Vec3d(0, 4, 4)};
  const int n = clip_polygon(&near, 1, poly, 3);
  ASSERT_EQ(n, 4);
  for (int i = 0; i < n; ++i) EXPECT_GE(poly[i].z(), 1.0 - 1e-12);
  // Crossing of the first edge, the two kept vertices, crossing of the last edge.
  EXPECT_TRUE(poly[0].isApprox(Vec3d(1, 0, 1)));
  EXPECT_EQ(poly[1], Vec3d(4, 0, 4));
  EXPECT_EQ(poly[2], Vec3d(0, 4, 4));
  EXPECT_TRUE(poly[3].isApprox(Vec3d(0, 1, 1)));
}

TEST(RasterClip, FullyOutsideGivesNothingAndFullyInsideIsUntouched) {
  const Vec4d near(0, 0, 1, -1);
  Vec3d out[kMaxClippedVertices] = {Vec3d(0, 0, 0), Vec3d(1, 0, 0.5), Vec3d(0, 1, 0.2)};
  EXPECT_EQ(clip_polygon(&near, 1, out, 3), 0);
  Vec3d in[kMaxClippedVertices] = {Vec3d(0, 0, 2), Vec3d(1, 0, 3), Vec3d(0, 1, 4)};
  EXPECT_EQ(clip_polygon(&near, 1, in, 3), 3);
  EXPECT_EQ(in[2], Vec3d(0, 1, 4));
}

TEST(RasterClip, SharedEdgeCrossingIsBitIdenticalFromBothSides) {
  const Vec4d planes[2] = {Vec4d(0, 0, 1, -0.05), Vec4d(1, 0, 0.3, 0.7)};
  const Vec3d a(0.1234567, -0.75, -0.3), b(-0.987, 0.333, 7.1);
  Vec3d t1[kMaxClippedVertices] = {a, b, Vec3d(2, 2, 3)};
  Vec3d t2[kMaxClippedVertices] = {b, a, Vec3d(-2, -1, 5)};
  const int n1 = clip_polygon(planes, 2, t1, 3), n2 = clip_polygon(planes, 2, t2, 3);
  ASSERT_GT(n1, 0);
  ASSERT_GT(n2, 0);
  // The crossing of a-b with the near plane appears in both polygons, bit for bit.
  int shared = 0;
  for (int i = 0; i < n1; ++i)
    for (int j = 0; j < n2; ++j) shared += t1[i] == t2[j] && std::abs(t1[i].z() - 0.05) < 1e-12;
  EXPECT_EQ(shared, 1);
}

TEST(RasterClip, FivePlanesNeverExceedTheVertexBound) {
  const Vec4d planes[5] = {Vec4d(0, 0, 1, -0.1), Vec4d(1, 0, 0, 1), Vec4d(-1, 0, 0, 1), Vec4d(0, 1, 0, 1),
                           Vec4d(0, -1, 0, 1)};
  Vec3d poly[kMaxClippedVertices] = {Vec3d(-5, -5, -1), Vec3d(5, -4, 3), Vec3d(0, 6, 2)};
  const int n = clip_polygon(planes, 5, poly, 3);
  ASSERT_GE(n, 3);
  ASSERT_LE(n, kMaxClippedVertices);
  for (int i = 0; i < n; ++i) {
    EXPECT_GE(poly[i].z(), 0.1 - 1e-12);
    EXPECT_LE(std::abs(poly[i].x()), 1.0 + 1e-12);
    EXPECT_LE(std::abs(poly[i].y()), 1.0 + 1e-12);
  }
}

}  // namespace
}  // namespace silva::render
