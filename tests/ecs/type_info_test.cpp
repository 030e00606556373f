#include "ecs/type_info.hpp"

#include <gtest/gtest.h>

#include <string_view>

namespace silva::ecs {
namespace {

struct Alpha {};
struct Beta {};

TEST(TypeInfo, IdsAreDistinctAndIgnoreConst) {
  EXPECT_NE(type_id<Alpha>(), type_id<Beta>());
  EXPECT_EQ(type_id<Alpha>(), type_id<const Alpha>());
}

TEST(TypeInfo, NamesAreReadable) {
  EXPECT_EQ(type_name<int>(), "int");
  const std::string_view alpha = type_name<const Alpha>();
  EXPECT_EQ(alpha.substr(0, 12), "silva::ecs::");
  EXPECT_EQ(alpha.substr(alpha.size() - 7), "::Alpha");
}

}  // namespace
}  // namespace silva::ecs
