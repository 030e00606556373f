#include "ecs/access.hpp"

#include <gtest/gtest.h>

namespace silva::ecs {
namespace {

struct P {};
struct V {};

TEST(Access, WriteImpliesReadAndWins) {
  Access a;
  a.declare<P>(AccessKind::component, false);
  EXPECT_TRUE(a.can_read(AccessKind::component, type_id<P>()));
  EXPECT_FALSE(a.can_write(AccessKind::component, type_id<P>()));
  a.declare<P>(AccessKind::component, true);
  a.declare<P>(AccessKind::component, false);
  EXPECT_TRUE(a.can_write(AccessKind::component, type_id<P>()));
  EXPECT_EQ(a.entries().size(), 1u);
  EXPECT_FALSE(a.can_read(AccessKind::resource, type_id<P>()));
}

TEST(Access, ClashesNeedAWriterOnTheSameKindAndType) {
  Access reader, writer, other, resource_writer;
  reader.declare<P>(AccessKind::component, false);
  writer.declare<P>(AccessKind::component, true);
  other.declare<V>(AccessKind::component, true);
  resource_writer.declare<P>(AccessKind::resource, true);
  EXPECT_TRUE(clashes(reader, reader).empty());
  EXPECT_TRUE(clashes(writer, other).empty());
  EXPECT_TRUE(clashes(writer, resource_writer).empty());
  const auto c = clashes(reader, writer);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].name, type_name<P>());
  EXPECT_FALSE(c[0].first_writes);
  EXPECT_TRUE(c[0].second_writes);
}

}  // namespace
}  // namespace silva::ecs
