#include "world/class_map.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "world/chunk_regions.hpp"
#include "tests/common/test_library.hpp"

namespace silva::world {

namespace {

/// Pixels of the map painted in the colour of `role`.
size_t count_role(const ClassMap& map, const Ontology& ontology, Role role) {
  const auto& c = ontology.color(role);
  size_t n = 0;
  for (size_t k = 0; k < map.rgb.size(); k += 3)
    n += map.rgb[k] == c[0] && map.rgb[k + 1] == c[1] && map.rgb[k + 2] == c[2];
  return n;
}

}  // namespace

TEST(ClassMap, CoversTheChunksAndShowsTrailAndSolids) {
  const WorldContext ctx = make_world_context(test::small_world_config(5, 10), test::small_library());
  const BuiltWorld w = test::build_world(ctx, chunks_in_disc(0, 0, 40, 32), 1);
  const Ontology ontology = default_ontology();
  const ClassMap map = render_class_map(w, 32, test::small_library(), ontology, 0.5);
  int i0 = 0, i1 = 0, j0 = 0, j1 = 0;
  for (const ChunkContent& c : w.chunks) {
    i0 = std::min(i0, c.coord.i), i1 = std::max(i1, c.coord.i);
    j0 = std::min(j0, c.coord.j), j1 = std::max(j1, c.coord.j);
  }
  EXPECT_EQ(map.width, (i1 - i0 + 1) * 64);
  EXPECT_EQ(map.height, (j1 - j0 + 1) * 64);
  ASSERT_EQ(map.rgb.size(), size_t(map.width) * map.height * 3);
  // The trail starts at the origin, which is inside the built disc; trunks are drawn on top.
  EXPECT_GT(count_role(map, ontology, Role::Trail), 100u);
  EXPECT_GT(count_role(map, ontology, Role::TreeTrunk), 10u);
  EXPECT_GT(count_role(map, ontology, Role::Background), 0u);  // the disc leaves corners unbuilt
}

}  // namespace silva::world
