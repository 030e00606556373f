#pragma once
/// @file Fluent registration of systems: world.system("name").phase(P).reads<A>().writes<B>().run(fn).
#include <cstddef>
#include <functional>
#include <string>
#include <type_traits>
#include <utility>

#include "ecs/access.hpp"
#include "ecs/fwd.hpp"
#include "ecs/scheduler.hpp"
#include "ecs/system.hpp"
#include "ecs/system_context.hpp"

namespace silva::ecs {

/// Collects a system's declaration; run(), each() or parallel_each() registers it.
class SystemBuilder {
 public:
  /// Starts declaring a system called `name` for `scheduler`.
  SystemBuilder(Scheduler& scheduler, std::string name) : scheduler_(scheduler) { system_.name = std::move(name); }

  /// Sets the phase (default 0); phases run in ascending order.
  SystemBuilder& phase(int p) {
    system_.phase = p;
    return *this;
  }
  /// Sets the phase from an enumerator.
  template <class E>
    requires std::is_enum_v<E>
  SystemBuilder& phase(E p) {
    return phase(static_cast<int>(p));
  }
  /// Declares read access to components Ts.
  template <class... Ts>
  SystemBuilder& reads() {
    (system_.access.declare<Ts>(AccessKind::component, false), ...);
    return *this;
  }
  /// Declares write (and read) access to components Ts.
  template <class... Ts>
  SystemBuilder& writes() {
    (system_.access.declare<Ts>(AccessKind::component, true), ...);
    return *this;
  }
  /// Declares read access to resources Ts.
  template <class... Ts>
  SystemBuilder& reads_resource() {
    (system_.access.declare<Ts>(AccessKind::resource, false), ...);
    return *this;
  }
  /// Declares write (and read) access to resources Ts.
  template <class... Ts>
  SystemBuilder& writes_resource() {
    (system_.access.declare<Ts>(AccessKind::resource, true), ...);
    return *this;
  }
  /// Orders this system after `other` (same phase: runs later; earlier phase: always true).
  SystemBuilder& after(std::string other) {
    system_.after.push_back(std::move(other));
    return *this;
  }
  /// Registers the system with `body` as its work.
  void run(std::function<void(SystemContext&)> body) {
    system_.body = std::move(body);
    scheduler_.add(std::move(system_));
  }
  /// Registers a system calling fn for each entity with all of Ts (see SystemContext::each);
  /// declares reads of `const T` and writes of the other Ts.
  template <class... Ts, class Fn>
  void each(Fn fn) {
    declare_view<Ts...>();
    run([fn = std::move(fn)](SystemContext& ctx) mutable { ctx.each<Ts...>(fn); });
  }
  /// Like each(), iterating fixed-size chunks in parallel (see SystemContext::parallel_each).
  template <class... Ts, class Fn>
  void parallel_each(Fn fn, std::size_t chunk_size = kDefaultChunkSize) {
    declare_view<Ts...>();
    run([fn = std::move(fn), chunk_size](SystemContext& ctx) mutable { ctx.parallel_each<Ts...>(fn, chunk_size); });
  }

 private:
  template <class... Ts>
  void declare_view() {
    (system_.access.declare<Ts>(AccessKind::component, !std::is_const_v<Ts>), ...);
  }

  Scheduler& scheduler_;
  System system_;
};

}  // namespace silva::ecs
