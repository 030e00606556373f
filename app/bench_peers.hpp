#pragma once
/// @file The rasteriser peers (bench/peers_bench: Mesa llvmpipe, Embree) as part of `silva bench`.
#include <filesystem>

#include <nlohmann/json.hpp>

namespace silva::app {

/// Runs `<dir of the silva binary>/bench/peers_bench --benchmark_format=json` when it exists:
/// {"ran": true, "program", "wall_s", "benchmarks": [Google Benchmark entries]}, else
/// {"ran": false, "note": why}.
nlohmann::json run_peers_bench(const std::filesystem::path& program);

/// Where peers_bench is built: <folder of the running silva binary>/bench/peers_bench.
std::filesystem::path peers_bench_path();

}  // namespace silva::app
