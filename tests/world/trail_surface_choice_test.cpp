// Trail surface families: named by the config, or drawn per seed.
#include "world/trail_surface_choice.hpp"

#include <gtest/gtest.h>

#include <set>

#include "core/error.hpp"

namespace silva::world {
namespace {

TEST(TrailSurfaceChoice, NamedFamiliesAndADrawPerSeed) {
  for (int f = 0; f < kTrailSurfaceCount; ++f)
    EXPECT_EQ(trail_surface_of(std::string(trail_surface_name(TrailSurface(f))), 3), TrailSurface(f));
  std::set<TrailSurface> drawn;
  for (uint64_t seed = 0; seed < 64; ++seed) {
    drawn.insert(trail_surface_of("random", seed));
    EXPECT_EQ(trail_surface_of("random", seed), trail_surface_of("random", seed));
  }
  EXPECT_EQ(drawn.size(), size_t(kTrailSurfaceCount));
}

TEST(TrailSurfaceChoice, AnUnknownNameListsTheFamilies) {
  try {
    trail_surface_of("cobbles", 1);
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("trail.surface"), std::string::npos);
    EXPECT_NE(what.find("cobbles"), std::string::npos);
    EXPECT_NE(what.find("grass_ruts"), std::string::npos);
    EXPECT_NE(what.find("random"), std::string::npos);
  }
}

}  // namespace
}  // namespace silva::world
