#pragma once
/// @file The markdown report of a `silva bench` results document.
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench/harness/bench_compare.hpp"

namespace silva::bench {

/// Name part of the chart drawn for `table` by scripts/bench_charts.py ("5.1" -> "generation-density";
/// "threads" for the scaling tables), or "" when the table has no chart.
std::string chart_suffix(const std::string& table);

/// The markdown report: machine, headline ratios, comparison with `previous_name` (the regressions
/// found; "" = no earlier results), one table per thesis table and thread scaling, the peers, and
/// `stem`-<suffix>.png charts that exist in `dir`.
std::string bench_markdown(const nlohmann::json& results, const std::string& previous_name,
                           const std::vector<Regression>& regressions, const std::filesystem::path& dir,
                           const std::string& stem);

}  // namespace silva::bench
