#include "core/cellular_noise.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

#include "core/value_noise.hpp"

namespace silva {
namespace {

/// Distances from (x, y, z) to every feature point of the 5x5x5 cells around it, nearest first,
/// from the placement cellular3 documents.
std::vector<double> brute_force_distances(float x, float y, float z, uint32_t salt) {
  std::vector<double> d;
  const int ix = int(std::floor(x)), iy = int(std::floor(y)), iz = int(std::floor(z));
  for (int k = iz - 2; k <= iz + 2; ++k)
    for (int j = iy - 2; j <= iy + 2; ++j)
      for (int i = ix - 2; i <= ix + 2; ++i) {
        const uint32_t h = lattice_hash(i, j, k, salt);
        const double fx = i + (h & 1023u) / 1024.0, fy = j + ((h >> 10) & 1023u) / 1024.0,
                     fz = k + ((h >> 20) & 1023u) / 1024.0;
        d.push_back(std::sqrt((fx - x) * (fx - x) + (fy - y) * (fy - y) + (fz - z) * (fz - z)));
      }
  std::sort(d.begin(), d.end());
  return d;
}

TEST(CellularNoise, FindsTheNearestTwoFeaturePoints) {
  for (int n = 0; n < 2000; ++n) {
    const float x = 0.137f * float(n) - 40.0f, y = 0.0731f * float(n) + 3.0f, z = -0.0519f * float(n);
    const CellularSample c = cellular3(x, y, z, 9);
    const std::vector<double> d = brute_force_distances(x, y, z, 9);
    EXPECT_NEAR(c.f1, d[0], 1e-4) << n;
    EXPECT_NEAR(c.f2, d[1], 1e-4) << n;
    EXPECT_EQ(c.f1, cellular3(x, y, z, 9).f1);
  }
}

TEST(CellularNoise, GapGradientMatchesFiniteDifferencesInsideCells) {
  const float h = 1e-3f;
  int checked = 0, matched = 0;
  for (int n = 0; n < 500; ++n) {
    const float x = 0.311f * float(n) - 7.0f, y = 0.173f * float(n) + 1.0f, z = 0.097f * float(n) - 3.0f;
    const CellularSample c = cellular3(x, y, z, 4);
    if (c.f2 - c.f1 < 0.05f) continue;  // by a border the nearest two may change within the step
    const auto gap = [](const CellularSample& s) { return s.f2 - s.f1; };
    const float dx = (gap(cellular3(x + h, y, z, 4)) - gap(cellular3(x - h, y, z, 4))) / (2 * h);
    const float dy = (gap(cellular3(x, y + h, z, 4)) - gap(cellular3(x, y - h, z, 4))) / (2 * h);
    const float dz = (gap(cellular3(x, y, z + h, 4)) - gap(cellular3(x, y, z - h, 4))) / (2 * h);
    ++checked;
    matched += std::abs(c.gap_dx - dx) < 0.02f && std::abs(c.gap_dy - dy) < 0.02f && std::abs(c.gap_dz - dz) < 0.02f;
  }
  EXPECT_GT(checked, 300);
  // Where a third point is as near as the second, the second changes within the step: a few.
  EXPECT_GE(matched, checked * 97 / 100);
}

TEST(CellularNoise, NeighbouringPointsShareACellAndSaltsDiffer) {
  std::set<uint32_t> cells;
  int same = 0, differ = 0;
  for (int n = 0; n < 1000; ++n) {
    const float x = 0.05f * float(n), y = 0.5f, z = 0.25f;
    const CellularSample c = cellular3(x, y, z, 1);
    cells.insert(c.nearest_cell);
    same += c.nearest_cell == cellular3(x + 1e-4f, y, z, 1).nearest_cell ? 1 : 0;
    differ += c.f1 != cellular3(x, y, z, 2).f1 ? 1 : 0;
  }
  EXPECT_GT(cells.size(), 30u);  // 50 cells long: most of them are someone's nearest
  EXPECT_GT(same, 990);
  EXPECT_GT(differ, 990);
}

}  // namespace
}  // namespace silva
