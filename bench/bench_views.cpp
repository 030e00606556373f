/// @file The numbered bench views (see bench_views.hpp).
#include "bench/bench_views.hpp"

#include <stdexcept>
#include <string>

#include "bench/default_view.hpp"
#include "bench/forest_scene.hpp"

namespace silva::bench {

BenchView bench_view(int64_t id) {
  if (id == 0) {
    const ForestScene& w = forest_scene();
    return {&w.scene, false, {&w.scene, &w.camera}, w.triangle_count()};
  }
  if (id == 1 || id == 2) {
    const DefaultView& v = default_view();
    const FrozenView& f = id == 1 ? v.drawn : v.full_detail;
    return {&v.frame.scene, id == 1, {&f.scene, &v.camera}, f.triangle_count()};
  }
  throw std::out_of_range("bench view " + std::to_string(id) +
                          " does not exist (0: stress forest, 1: default view, 2: default view at full detail)");
}

void views_and_threads(benchmark::internal::Benchmark* b) {
  b->ArgsProduct({{0, 1, 2}, {1, 2}})->ArgNames({"view", "threads"})->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);
}

}  // namespace silva::bench
