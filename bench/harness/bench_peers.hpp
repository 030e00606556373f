#pragma once
/// @file The rasteriser peers (bench/peers_bench: Mesa llvmpipe, Embree) as part of `silva bench`.
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

namespace silva::app {

/// What became of one peers_bench benchmark.
struct PeerOutcome {
  std::string status;  ///< "ran", "not built" or "did not run".
  std::string note;    ///< Why it has no time ("" when it ran).
};

/// Reads one Google Benchmark entry of peers_bench: an entry with an error (SkipWithError) or
/// without a positive time has no figure; one whose error says peers_bench was built without the
/// peer is "not built" and says what to install.
PeerOutcome peer_outcome(const nlohmann::json& benchmark);

/// The peers section of the markdown report: one row per benchmark with its time, or why it has
/// none ("not built: install libembree-dev and rebuild"); never a zero time.
std::string peers_markdown(const nlohmann::json& peers);

/// Runs `<dir of the silva binary>/bench/peers_bench --benchmark_format=json` when it exists:
/// {"ran": true, "program", "wall_s", "benchmarks": [Google Benchmark entries, each with "status" and
/// "note" of peer_outcome added and, where it did not run, real_time and cpu_time null]}, else
/// {"ran": false, "note": why}.
nlohmann::json run_peers_bench(const std::filesystem::path& program);

/// Where peers_bench is built: <folder of the running silva binary>/bench/peers_bench.
std::filesystem::path peers_bench_path();

}  // namespace silva::app
