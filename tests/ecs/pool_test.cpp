#include "ecs/pool.hpp"

#include <gtest/gtest.h>

namespace silva::ecs {
namespace {

TEST(Pool, PutStoresAndReplaces) {
  Pool<int> p;
  p.put(Entity{3, 0}, 30);
  p.put(Entity{1, 0}, 10);
  EXPECT_EQ(p.size(), 2u);
  EXPECT_EQ(p.get(Entity{3, 0}), 30);
  p.put(Entity{3, 0}, 33);
  EXPECT_EQ(p.size(), 2u);
  EXPECT_EQ(p.get(Entity{3, 0}), 33);
}

TEST(Pool, ContainsChecksGeneration) {
  Pool<int> p;
  p.put(Entity{2, 1}, 7);
  EXPECT_TRUE(p.contains(Entity{2, 1}));
  EXPECT_FALSE(p.contains(Entity{2, 0}));
  EXPECT_FALSE(p.contains(Entity{9, 0}));
}

TEST(Pool, RemoveSwapsLastIntoHoleKeepingArraysAligned) {
  Pool<int> p;
  for (std::uint32_t i = 0; i < 4; ++i) p.put(Entity{i, 0}, int(i) * 10);
  EXPECT_TRUE(p.remove(Entity{1, 0}));
  EXPECT_FALSE(p.remove(Entity{1, 0}));
  ASSERT_EQ(p.size(), 3u);
  const auto ents = p.entities();
  const auto vals = p.components();
  EXPECT_EQ(ents[1], (Entity{3, 0}));
  for (std::size_t i = 0; i < p.size(); ++i) EXPECT_EQ(vals[i], int(ents[i].index) * 10);
  EXPECT_EQ(p.get(Entity{3, 0}), 30);
}

TEST(Pool, NamedAfterItsType) {
  Pool<double> p;
  EXPECT_EQ(p.name(), "double");
}

}  // namespace
}  // namespace silva::ecs
