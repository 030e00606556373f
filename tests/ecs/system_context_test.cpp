#include "ecs/system_context.hpp"

#include <gtest/gtest.h>

#include <string>

#include "ecs/world.hpp"

namespace silva::ecs {
namespace {

struct Pos {
  int v = 0;
};
struct Vel {
  int v = 0;
};
struct Gravity {
  int g = 0;
};

TEST(SystemContext, UndeclaredAccessThrowsNamingSystemAndType) {
  World w;
  w.spawn(Pos{1}, Vel{2});
  w.set_resource(Gravity{3});
  std::string message;
  w.system("sneaky").reads<Pos>().run([&](SystemContext& ctx) {
    ctx.view<const Pos>();                                  // declared: fine
    EXPECT_THROW(ctx.view<Pos>(), Error);                   // write needs writes<Pos>()
    EXPECT_THROW((ctx.view<const Pos, const Vel>()), Error);  // Vel undeclared
    EXPECT_THROW(ctx.resource<const Gravity>(), Error);
    try {
      ctx.view<Vel>();
    } catch (const Error& e) {
      message = e.what();
    }
  });
  w.run_frame();
  EXPECT_NE(message.find("'sneaky'"), std::string::npos) << message;
  EXPECT_NE(message.find("Vel"), std::string::npos) << message;
}

TEST(SystemContext, DeclaredResourceAndComponentAccessWorks) {
  World w;
  const Entity e = w.spawn(Pos{1}, Vel{2});
  w.set_resource(Gravity{10});
  w.system("fall").reads_resource<Gravity>().reads<Vel>().writes<Pos>().run([](SystemContext& ctx) {
    const int g = ctx.resource<const Gravity>().g;
    ctx.view<Pos, const Vel>().each([&](Pos& p, const Vel& v) { p.v += v.v * g; });
  });
  w.run_frame();
  EXPECT_EQ(w.get<Pos>(e).v, 21);
}

TEST(SystemContext, EachDeclaresAccessFromConstness) {
  World w;
  w.spawn(Pos{1}, Vel{2});
  w.system("move").each<Pos, const Vel>([](Pos& p, const Vel& v) { p.v += v.v; });
  w.system("also_writes_pos").writes<Pos>().run([](SystemContext&) {});
  ASSERT_EQ(w.schedule_conflicts().size(), 1u);
  EXPECT_EQ(w.schedule_conflicts()[0].clash.name, type_name<Pos>());
  World ok;
  const Entity f = ok.spawn(Pos{1}, Vel{2});
  ok.system("move").each<Pos, const Vel>([](Pos& p, const Vel& v) { p.v += v.v; });
  ok.system("read_vel").reads<Vel>().run([](SystemContext&) {});
  ok.run_frame();
  EXPECT_EQ(ok.get<Pos>(f).v, 3);
}

TEST(SystemContext, EachWithCommandBufferDefersStructuralChanges) {
  World w;
  for (int i = 0; i < 10; ++i) w.spawn(Pos{i});
  w.system("cull").each<const Pos>([](CommandBuffer& cb, Entity e, const Pos& p) {
    if (p.v % 2 == 0) cb.despawn(e);
  });
  w.run_frame();
  EXPECT_EQ(w.entity_count(), 5u);
}

}  // namespace
}  // namespace silva::ecs
