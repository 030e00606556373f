#pragma once
/// @file The Google Benchmark programs `silva bench` runs beside its own measurements (bench/peers_bench:
/// the rasteriser against Mesa llvmpipe and Embree; bench/view_bench: `silva view`'s frames;
/// bench/lidar_bench: the LiDAR sweep and scene update), each read back from its JSON output.
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

namespace silva::bench {

/// What became of one benchmark of a program.
struct ProgramOutcome {
  std::string status;  ///< "ran", "not built" or "did not run".
  std::string note;    ///< Why it has no time ("" when it ran).
};

/// Reads one Google Benchmark entry: an entry with an error (SkipWithError) or without a positive
/// time has no figure; one whose error says the program was built without a part ("built without
/// ... (Debian: <packages>)") is "not built" and says what to install.
ProgramOutcome program_outcome(const nlohmann::json& benchmark);

/// A section of the markdown report titled `title`: one row per benchmark with its time and user
/// counters, or why it has none ("not built: install libembree-dev and rebuild"); never a zero time.
std::string program_markdown(const std::string& title, const nlohmann::json& run);

/// Runs `program --benchmark_format=json` (with `--benchmark_filter=<filter>` unless `filter` is
/// empty) when it exists: {"ran": true, "program", "filter", "wall_s", "benchmarks": [Google Benchmark
/// entries, each with "status" and "note" of program_outcome added and, where it did not run,
/// real_time and cpu_time null]}, else {"ran": false, "note": why}.
nlohmann::json run_bench_program(const std::filesystem::path& program, const std::string& filter);

/// Where bench program `name` is built: <folder of the running silva binary>/bench/<name>.
std::filesystem::path bench_program_path(const std::string& name);

}  // namespace silva::bench
