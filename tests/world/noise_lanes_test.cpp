// fbm2_lanes returns core/noise.hpp's fbm2 bit for bit on every Highway target.
#include "world/noise_lanes.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <vector>

#include "core/rng.hpp"
#include "tests/render/highway_targets.hpp"

namespace silva::world {
namespace {

TEST(NoiseLanes, EqualsScalarFbmOnEveryHighwayTarget) {
  // Lengths that end inside a vector; points either side of zero, on lattice lines and far out.
  FbmParams params;
  params.octaves = 5;
  params.frequency = 0.013;
  params.persistence = 0.47;
  params.lacunarity = 2.1;
  params.offset_x = -1234.567;
  params.offset_y = 987.25;
  Rng rng(7, 0, Purpose::TerrainOffset);
  std::vector<double> x, y;
  for (int k = 0; k < 1000; ++k) {
    x.push_back(rng.uniform_double() * 4000.0 - 2000.0);
    y.push_back(rng.uniform_double() * 4000.0 - 2000.0);
  }
  for (int k = -20; k <= 20; ++k) {  // whole and half metres, where floors and corner choices flip
    x.push_back(0.5 * k);
    y.push_back(-0.5 * k);
  }
  x.push_back(-0.0);
  y.push_back(0.0);
  for (size_t n : {size_t(1), size_t(3), size_t(7), x.size()}) {
    for (int64_t target : render::test::highway_targets()) {
      SCOPED_TRACE(hwy::TargetName(target));
      const render::test::PinnedTarget pin(target);
      EXPECT_EQ(fbm2_lanes_simd_target(), target);
      std::vector<double> out(n, -7.0);
      fbm2_lanes(params, x.data(), y.data(), out.data(), n);
      size_t differing = 0;
      for (size_t k = 0; k < n; ++k)
        differing += std::bit_cast<uint64_t>(out[k]) != std::bit_cast<uint64_t>(fbm2(params, x[k], y[k])) ? 1 : 0;
      EXPECT_EQ(differing, 0u) << n << " points";
    }
  }
}

TEST(NoiseLanes, NoOctavesGiveZero) {
  FbmParams params;
  params.octaves = 0;
  const double x[2] = {1.0, 2.0}, y[2] = {3.0, 4.0};
  double out[2] = {5.0, 5.0};
  fbm2_lanes(params, x, y, out, 2);
  EXPECT_EQ(out[0], 0.0);
  EXPECT_EQ(out[1], 0.0);
}

}  // namespace
}  // namespace silva::world
