#include "ecs/registry.hpp"

#include <gtest/gtest.h>

#include <string>

namespace silva::ecs {
namespace {

struct Position {
  float x = 0, y = 0;
};
struct Health {
  int hp = 0;
};

TEST(Registry, AddHasGetRemove) {
  Registry r;
  const Entity e = r.spawn();
  EXPECT_FALSE(r.has<Position>(e));
  r.add(e, Position{1, 2});
  EXPECT_TRUE(r.has<Position>(e));
  EXPECT_FALSE(r.has<Health>(e));
  EXPECT_EQ(r.get<Position>(e).y, 2.0f);
  r.get<Position>(e).x = 5;
  EXPECT_EQ(r.get<const Position>(e).x, 5.0f);
  r.add(e, Position{7, 8});
  EXPECT_EQ(r.get<Position>(e).x, 7.0f);
  EXPECT_TRUE(r.remove<Position>(e));
  EXPECT_FALSE(r.remove<Position>(e));
  EXPECT_FALSE(r.has<Position>(e));
  EXPECT_EQ(r.try_get<Position>(e), nullptr);
}

TEST(Registry, SpawnWithComponents) {
  Registry r;
  const Entity e = r.spawn(Position{1, 1}, Health{9});
  EXPECT_EQ(r.get<Health>(e).hp, 9);
  EXPECT_TRUE(r.has<Position>(e));
  EXPECT_EQ(r.entity_count(), 1u);
}

TEST(Registry, StaleHandleIsDetectedAndNeverAliasesTheNewEntity) {
  Registry r;
  const Entity old = r.spawn(Health{1});
  ASSERT_TRUE(r.despawn(old));
  const Entity fresh = r.spawn(Health{2});
  ASSERT_EQ(fresh.index, old.index);  // the slot is reused...
  EXPECT_FALSE(r.alive(old));         // ...but the old handle stays dead
  EXPECT_TRUE(r.alive(fresh));
  EXPECT_FALSE(r.has<Health>(old));
  EXPECT_EQ(r.try_get<Health>(old), nullptr);
  EXPECT_FALSE(r.despawn(old));
  EXPECT_FALSE(r.remove<Health>(old));
  EXPECT_EQ(r.get<Health>(fresh).hp, 2);
  try {
    r.get<Health>(old);
    FAIL() << "get on a stale handle must throw";
  } catch (const Error& err) {
    EXPECT_NE(std::string(err.what()).find("stale"), std::string::npos) << err.what();
    EXPECT_NE(std::string(err.what()).find(to_string(old)), std::string::npos) << err.what();
  }
  EXPECT_THROW(r.add(old, Health{3}), Error);
  EXPECT_EQ(r.get<Health>(fresh).hp, 2);
}

TEST(Registry, GetOfMissingComponentThrowsNamingIt) {
  Registry r;
  const Entity e = r.spawn(Health{1});
  try {
    r.get<Position>(e);
    FAIL() << "get of a missing component must throw";
  } catch (const Error& err) {
    EXPECT_NE(std::string(err.what()).find("Position"), std::string::npos) << err.what();
  }
}

TEST(Registry, DespawnRemovesEveryComponent) {
  Registry r;
  const Entity a = r.spawn(Position{}, Health{1});
  const Entity b = r.spawn(Position{}, Health{2});
  r.despawn(a);
  EXPECT_EQ(r.pool<Position>().size(), 1u);
  EXPECT_EQ(r.pool<Health>().size(), 1u);
  EXPECT_EQ(r.get<Health>(b).hp, 2);
  EXPECT_EQ(r.entity_count(), 1u);
}

}  // namespace
}  // namespace silva::ecs
