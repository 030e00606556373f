#pragma once
/// @file Every measurement of `silva bench`, as one results document (no files but scratch).
#include <nlohmann/json.hpp>

#include "bench/harness/bench_context.hpp"

namespace silva::bench {

/// Runs generation, capture, autopilot and thread scaling for `ctx` and returns the results document:
/// {"harness": "silva-bench", "kind", "created_utc", "cpu_slug", "machine", "thesis_machine",
///  "plan", "setup_s", "tables": {key: title}, "figures": [figure_json...], "wall_s", "load_average_end",
///  "interrupted"}. After Ctrl-C it stops early and returns the figures measured so far with
///  "interrupted": true.
nlohmann::json run_bench_suite(const BenchContext& ctx, double setup_s);

/// The current UTC time as "YYYY-MM-DDTHH:MM:SSZ".
std::string utc_now();

}  // namespace silva::bench
