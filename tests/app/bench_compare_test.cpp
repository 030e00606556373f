#include "bench/harness/bench_compare.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "silva_process.hpp"

namespace silva::bench {
namespace {

/// A results document with one figure per (table, x, seconds).
nlohmann::json results(std::vector<std::tuple<std::string, std::string, double>> figures) {
  nlohmann::json doc = {{"harness", "silva-bench"}, {"figures", nlohmann::json::array()}};
  for (const auto& [table, x, s] : figures) doc["figures"].push_back({{"table", table}, {"x", x}, {"silva_s", s}});
  return doc;
}

TEST(BenchCompare, FlagsTenPercentWorseNotNine) {
  const auto before = results({{"5.1", "5", 2.0}, {"5.6", "1920x1080", 1.0}});
  const auto after = results({{"5.1", "5", 2.2}, {"5.6", "1920x1080", 1.09}});
  const auto regressions = compare_results(before, after);
  ASSERT_EQ(regressions.size(), 1u);
  EXPECT_EQ(regressions[0].table, "5.1");
  EXPECT_EQ(regressions[0].x, "5");
  EXPECT_NEAR(regressions[0].change, 0.10, 1e-12);
  EXPECT_DOUBLE_EQ(regressions[0].before_s, 2.0);
  EXPECT_DOUBLE_EQ(regressions[0].after_s, 2.2);
}

TEST(BenchCompare, FasterUnmatchedAndNonPositiveFiguresAreNotFlagged) {
  const auto before = results({{"5.1", "5", 2.0}, {"5.9", "rgb_to_depth", -0.01}, {"5.7", "100", 10.0}});
  const auto after = results({{"5.1", "5", 1.0}, {"5.9", "rgb_to_depth", 0.5}, {"5.2", "5", 100.0}, {"5.7", "50", 99.0}});
  EXPECT_TRUE(compare_results(before, after).empty());
}

TEST(BenchCompare, PreviousResultsIsTheNewestOfTheSameKindAndCpu) {
  const auto dir = test::fresh_test_dir();
  const auto write = [&](const std::string& name, nlohmann::json doc) { std::ofstream(dir / name) << doc.dump(); };
  const auto doc = [](std::string kind, std::string cpu, std::string created) {
    return nlohmann::json{{"harness", "silva-bench"}, {"kind", kind}, {"cpu_slug", cpu}, {"created_utc", created}};
  };
  write("a.json", doc("full", "cpu-a", "2026-11-20T10:00:00Z"));
  write("b.json", doc("full", "cpu-a", "2026-11-22T10:00:00Z"));
  write("c.json", doc("quick", "cpu-a", "2026-11-23T10:00:00Z"));
  write("d.json", doc("full", "cpu-b", "2026-11-23T10:00:00Z"));
  write("raw-google-benchmark.json", {{"benchmarks", nlohmann::json::array()}});
  std::ofstream(dir / "broken.json") << "{ not json";
  EXPECT_EQ(previous_results(dir, "full", "cpu-a")->filename(), "b.json");
  EXPECT_EQ(previous_results(dir, "quick", "cpu-a")->filename(), "c.json");
  EXPECT_FALSE(previous_results(dir, "quick", "cpu-b").has_value());
}

}  // namespace
}  // namespace silva::bench
