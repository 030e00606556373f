#include "ecs/resources.hpp"

#include <gtest/gtest.h>

#include <string>

namespace silva::ecs {
namespace {

struct Settings {
  int threads = 1;
};

TEST(Resources, SetGetReplaceErase) {
  Resources res;
  EXPECT_EQ(res.find<Settings>(), nullptr);
  res.set(Settings{4});
  EXPECT_EQ(res.get<Settings>().threads, 4);
  res.get<Settings>().threads = 5;
  EXPECT_EQ(res.get<const Settings>().threads, 5);
  res.set(Settings{6});
  EXPECT_EQ(res.get<Settings>().threads, 6);
  EXPECT_TRUE(res.erase<Settings>());
  EXPECT_FALSE(res.erase<Settings>());
}

TEST(Resources, MissingResourceThrowsNamingIt) {
  Resources res;
  try {
    res.get<Settings>();
    FAIL() << "get of an unset resource must throw";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("Settings"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace silva::ecs
