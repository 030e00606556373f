#pragma once
/// @file Generation figures of `silva bench`: thesis Tables 5.1-5.4b and generation thread scaling.
#include <vector>

#include "bench/harness/bench_context.hpp"

namespace silva::bench {

/// Tables 5.1 (density), 5.2 (max elevation), 5.3 (time of day), 5.4 (trail on/off) and 5.4b (no
/// ground vegetation): the median of plan.generation_repeats builds of the default world, each
/// timed from the world context (terrain field, trail) to the last resolved chunk. Figures are
/// appended to `out` as they are measured; throws Interrupted between points after Ctrl-C.
void bench_generation(const BenchContext& ctx, std::vector<Figure>& out);

/// "threads-generation": the default world built on 1..n threads (tbb::task_arena).
void bench_generation_threads(const BenchContext& ctx, std::vector<Figure>& out);

}  // namespace silva::bench
