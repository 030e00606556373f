#pragma once
/// @file Comparing a `silva bench` results file with an earlier one: which figures got slower.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace silva::bench {

/// A figure worse than the threshold against the earlier results.
struct Regression {
  std::string table;     ///< Table key.
  std::string x;         ///< The varied value.
  double before_s = 0;   ///< Earlier Silva time, seconds.
  double after_s = 0;    ///< Current Silva time, seconds.
  double change = 0;     ///< after / before - 1 (0.10 = 10 % slower).
};

/// Fraction by which a figure must be slower to be flagged.
inline constexpr double kRegressionThreshold = 0.10;

/// Figures of `current` (a results document) that are at least `threshold` slower than the figure
/// with the same table and x in `previous`; figures with a non-positive earlier time are skipped.
std::vector<Regression> compare_results(const nlohmann::json& previous, const nlohmann::json& current,
                                        double threshold = kRegressionThreshold);

/// The most recent (by "created_utc") `silva bench` results file in `dir` of the given kind
/// ("full"/"quick") measured on the CPU with slug `cpu`, if any; unreadable files are skipped.
std::optional<std::filesystem::path> previous_results(const std::filesystem::path& dir, const std::string& kind,
                                                      const std::string& cpu);

}  // namespace silva::bench
