#include "bench/harness/bench_suite.hpp"

#include <gtest/gtest.h>

#include <set>

#include "bench/harness/bench_machine.hpp"
#include "bench/harness/bench_report.hpp"
#include "silva_process.hpp"

namespace silva::bench {
namespace {

/// A tiny sweep (128 m world, 64x48 frames, 1-2 frames a point) that still measures every table.
BenchPlan tiny_plan() {
  BenchPlan p = quick_plan(2);
  p.kind = "test";
  p.overrides = {"world.extent=128", "world.render_distance=32", "trail.control_points=6", "camera.far=40",
                 "output.resolution=64x48", "captures.autopilot_points=4"};
  p.frames_per_point = 1;
  p.captures_max = 2;
  p.autopilot_frames = 6;
  p.scaling_frames = 3;
  p.threads = {1, 2};
  return p;
}

/// The results of the tiny sweep (run once for every test of this file).
const nlohmann::json& tiny_results() {
  static const nlohmann::json doc = [] {
    const Reporter quiet(OutputFlags{false, true});
    const auto scratch = std::filesystem::temp_directory_path() / ("silva-bench-test-" + std::to_string(getpid()));
    const BenchContext ctx = make_bench_context(
        tiny_plan(), ThesisTables::load(std::string(SILVA_SOURCE_DIR) + "/bench/thesis-tables.json"), scratch, quiet, 2);
    nlohmann::json out = run_bench_suite(ctx, 0.0);
    EXPECT_FALSE(std::filesystem::exists(scratch) && !std::filesystem::is_empty(scratch)) << "capture output left behind";
    std::filesystem::remove_all(scratch);
    return out;
  }();
  return doc;
}

/// Every thesis table and every thesis x is measured.
void check_every_table(const nlohmann::json& doc) {
  const ThesisTables thesis = ThesisTables::load(std::string(SILVA_SOURCE_DIR) + "/bench/thesis-tables.json");
  for (const char* table : {"5.1", "5.2", "5.3", "5.4", "5.4b", "5.5", "5.6", "5.7", "5.8", "5.9", "autopilot"}) {
    EXPECT_TRUE(doc["tables"].contains(table)) << table;
    std::set<std::string> xs;
    for (const auto& f : doc["figures"])
      if (f["table"] == table) xs.insert(f["x"].get<std::string>());
    if (std::string(table) == "autopilot") {
      EXPECT_EQ(xs, std::set<std::string>{"12"}) << "4 points x 3 yaws";
    } else {
      const auto want = thesis.xs(table);
      EXPECT_EQ(xs, std::set<std::string>(want.begin(), want.end())) << table;
    }
  }
}

/// Every figure has work counts and (thesis tables) a ratio.
void check_work_and_ratios(const nlohmann::json& doc) {
  for (const auto& f : doc["figures"]) {
    const std::string table = f["table"];
    const auto& w = f["work"];
    SCOPED_TRACE(table + " x=" + f["x"].get<std::string>());
    EXPECT_GT(w["objects"].get<uint64_t>(), 0u);
    EXPECT_GT(w["chunks"].get<uint64_t>(), 0u);
    EXPECT_GT(w["triangles"].get<uint64_t>(), 0u);
    const bool generation = table.rfind("5.", 0) == 0 && table < "5.5";
    if (generation || table == "threads-generation") {
      EXPECT_EQ(w["frames"].get<uint64_t>(), 0u);
    } else {
      EXPECT_GT(w["frames"].get<uint64_t>(), 0u);
      EXPECT_EQ(w["pixels"].get<uint64_t>() % w["frames"].get<uint64_t>(), 0u);
      EXPECT_GT(w["bytes"].get<uint64_t>(), 0u);
    }
    if (table.rfind("threads", 0) == 0) {
      EXPECT_TRUE(f["ratio"].is_null());
    } else {
      ASSERT_FALSE(f["thesis_s"].is_null());
      EXPECT_NEAR(f["ratio"].get<double>(), f["silva_s"].get<double>() / f["thesis_s"].get<double>(), 1e-12);
    }
    if (table != "5.9") {
      EXPECT_GT(f["silva_s"].get<double>(), 0.0);
    }
  }
}

/// Figures for runs larger than measured are marked extrapolated, measured ones are not.
void check_extrapolated(const nlohmann::json& doc) {
  for (const auto& f : doc["figures"]) {
    if (f["table"] == "5.7") {
      EXPECT_EQ(f["extrapolated"].get<bool>(), std::stoi(f["x"].get<std::string>()) > 2) << f["x"];
    } else if (f["table"] == "autopilot") {
      EXPECT_TRUE(f["extrapolated"].get<bool>());
    } else if (f["table"] == "5.1") {
      EXPECT_FALSE(f["extrapolated"].get<bool>());
    }
  }
}

/// The varied settings change the generated world (and the time of day does not).
void check_generation_work(const nlohmann::json& doc) {
  std::map<std::string, nlohmann::json> by;
  for (const auto& f : doc["figures"]) by[f["table"].get<std::string>() + "/" + f["x"].get<std::string>()] = f;
  const auto hash = [&](const std::string& key) { return by[key]["breakdown"]["world_hash"].get<std::string>(); };
  EXPECT_NE(hash("5.1/1"), hash("5.1/25"));
  EXPECT_NE(hash("5.4/true"), hash("5.4/false"));
  EXPECT_LT(by["5.4b/false"]["work"]["objects"].get<uint64_t>(), by["5.1/5"]["work"]["objects"].get<uint64_t>())
      << "no grass and ferns";
  EXPECT_EQ(hash("5.3/day"), hash("5.3/night")) << "the world does not depend on the time of day";
  EXPECT_EQ(hash("5.3/day"), hash("5.1/5")) << "the defaults";
}

/// The markdown report shows every table, the machine and the comparison.
void check_report(const nlohmann::json& doc) {
  const std::string md = bench_markdown(doc, "", {}, test::fresh_test_dir(), "x");
  for (const char* table : {"5.1", "5.2", "5.3", "5.4", "5.4b", "5.5", "5.6", "5.7", "5.8", "5.9"})
    EXPECT_NE(md.find(std::string("## Table ") + table + " "), std::string::npos) << table;
  EXPECT_NE(md.find("## Thread scaling"), std::string::npos);
  EXPECT_NE(md.find(doc["machine"]["cpu"].get<std::string>()), std::string::npos);
  EXPECT_NE(md.find("No earlier results"), std::string::npos);
  const std::string flagged = bench_markdown(doc, "old.json", {{"5.1", "5", 1.0, 1.2, 0.2}}, test::fresh_test_dir(), "x");
  EXPECT_NE(flagged.find("| 5.1 | 5 | 1.00 | 1.20 | +20.0 % |"), std::string::npos);
}

// One test (one process under ctest) so the tiny sweep runs once.
TEST(BenchSuite, TinySweepMeasuresEveryTableWithWorkCountsAndReportsIt) {
  const nlohmann::json& doc = tiny_results();
  EXPECT_FALSE(doc["interrupted"].get<bool>());
  check_every_table(doc);
  check_work_and_ratios(doc);
  check_extrapolated(doc);
  check_generation_work(doc);
  check_report(doc);
}

TEST(BenchMachine, CpuSlugIsFileNameSafe) {
  EXPECT_EQ(cpu_slug("AMD EPYC 7B13 64-Core Processor"), "amd-epyc-7b13-64-core");
  EXPECT_EQ(cpu_slug("Intel(R) Xeon(R) CPU @ 2.20GHz"), "intel-xeon-2.20ghz");
  EXPECT_EQ(cpu_slug(""), "unknown-cpu");
}

TEST(BenchPlan, ScalingThreadsEndAtTheCoreCount) {
  EXPECT_EQ(scaling_threads(1), std::vector<int>({1}));
  EXPECT_EQ(scaling_threads(2), std::vector<int>({1, 2}));
  EXPECT_EQ(scaling_threads(16), std::vector<int>({1, 2, 3, 4, 8, 16}));
  EXPECT_EQ(scaling_threads(6), std::vector<int>({1, 2, 3, 4, 6}));
}

}  // namespace
}  // namespace silva::bench
