#pragma once
/// @file The views the rasteriser benches draw, by number (the benchmarks' `view` argument):
/// 0 = the synthetic stress forest (bench/forest_scene.hpp, render.lod = false),
/// 1 = the product's default forest view (bench/default_view.hpp, LODs on),
/// 2 = the same view at full detail (render.lod = false).
#include <cstddef>
#include <cstdint>

#include <benchmark/benchmark.h>

#include "bench/peer_frame.hpp"
#include "render/render_options.hpp"

namespace silva::bench {

/// One view as each renderer is given it.
struct BenchView {
  const render::Scene* silva_scene = nullptr;  ///< What Silva draws (all LODs when `lod`).
  bool lod = false;                            ///< render.lod of Silva's pass.
  PeerView peers;                              ///< What the peers draw: lods[0] of the instances Silva draws.
  size_t triangles = 0;                        ///< Triangles of the peers' scene.
  /// Silva's render options for the view.
  render::RenderOptions options() const {
    render::RenderOptions opt;
    opt.lod = lod;
    return opt;
  }
};

/// View `id` (0, 1 or 2; anything else throws std::out_of_range), built on first use.
BenchView bench_view(int64_t id);

/// Google Benchmark registration shared by the view benches: arguments (view 0/1/2, threads 1/2),
/// milliseconds, wall time, at least 2 s each.
void views_and_threads(benchmark::internal::Benchmark* b);

}  // namespace silva::bench
