#pragma once
/// @file What a user waits for: `silva world` of the harness's default world timed as a whole process
/// (start, config, asset library, world context, build, exit), beside the in-harness build figure.
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench/harness/bench_plan.hpp"

namespace silva::bench {

/// Runs of the whole process the harness takes the median of.
inline constexpr int kProcessRuns = 3;

/// The running program when it is the `silva` binary (/proc/self/exe named "silva"), else "" (a
/// test program must not start itself).
std::filesystem::path silva_binary_path();

/// The arguments of `silva world` for the plan's default world: the harness seed, the plan's
/// overrides, `threads` threads, --json --quiet.
std::vector<std::string> whole_process_args(const BenchPlan& plan, int threads);

/// Runs `silva` with whole_process_args `runs` times (stdout and stderr discarded) and returns
/// {"ran": true, "command", "runs", "wall_s" (median), "min_s", "max_s", "cpu_s" (of the median
/// run)}, or {"ran": false, "note": why} when `silva` is "" or a run fails.
nlohmann::json time_whole_process(const std::filesystem::path& silva, const BenchPlan& plan, int threads,
                                  int runs = kProcessRuns);

/// The default-world generation figure (Table 5.1 at the default density) beside the whole process:
/// {"build_s", "process_wall_s" (null when the process did not run), "difference_s" (or null),
/// "explanation", "process": `process`}.
nlohmann::json generation_and_process(const nlohmann::json& results, const nlohmann::json& process);

/// The markdown section showing both generation figures side by side and what the difference is.
std::string generation_process_markdown(const nlohmann::json& generation_process);

}  // namespace silva::bench
