// The harness says what it did not measure: peers that were not built or did not run have no
// time (never 0), and the generation figure stands beside the whole `silva world` process.
#include <gtest/gtest.h>

#include <algorithm>

#include "bench/harness/bench_programs.hpp"
#include "bench/harness/bench_process.hpp"
#include "bench/harness/bench_report.hpp"

namespace silva::bench {
namespace {

/// A results document with just what bench_markdown reads, the figure of Table 5.1 at 5 % and `peers`.
nlohmann::json results_with(const nlohmann::json& peers) {
  return {{"kind", "test"},
          {"created_utc", "2000-01-01T00:00:00Z"},
          {"machine",
           {{"cpu", "cpu"}, {"cores", 2}, {"memory_gib", 4.0}, {"os", "os"}, {"kernel", "k"}, {"compiler", "c"},
            {"git_revision", "r"}, {"load_average_start", 0.0}}},
          {"wall_s", 1.0},
          {"thesis_machine", "thesis"},
          {"tables", nlohmann::json::object()},
          {"figures", {{{"table", "5.1"}, {"x", "5"}, {"silva_s", 0.84}, {"ratio", nullptr}}}},
          {"peers", peers}};
}

/// peers_bench's Google Benchmark output on a build without Embree: BM_Embree skipped with an error, time 0.
nlohmann::json peers_without_embree() {
  return {{"ran", true},
          {"program", "bench/peers_bench"},
          {"benchmarks",
           {{{"name", "BM_Silva/0/1"}, {"real_time", 12.5}, {"cpu_time", 12.4}, {"time_unit", "ms"}},
            {{"name", "BM_Embree/0/1"},
             {"error_occurred", true},
             {"error_message", "built without the Embree peer: Embree 3 not found (Debian: libembree-dev)"},
             {"real_time", 0.0},
             {"cpu_time", 0.0},
             {"time_unit", "ms"}}}}};
}

TEST(BenchPeers, APeerThatWasNotBuiltSaysSoAndReportsNoTime) {
  const std::string md = bench_markdown(results_with(peers_without_embree()), "", {}, "/nonexistent", "x");
  EXPECT_NE(md.find("| BM_Silva/0/1 | 12.500 | ms |"), std::string::npos) << md;
  EXPECT_NE(md.find("| BM_Embree/0/1 | not built: install libembree-dev and rebuild"), std::string::npos) << md;
  EXPECT_EQ(md.find("0.000"), std::string::npos) << "a peer that did not run must never report zero:\n" << md;
}

TEST(BenchPrograms, SectionsShowTheUserCountersOfEachBenchmark) {
  nlohmann::json results = results_with(peers_without_embree());
  results["view"] = {{"ran", true},
                     {"program", "bench/view_bench"},
                     {"filter", "BM_ViewFrameMoving/threads:2"},
                     {"benchmarks",
                      {{{"name", "BM_ViewFrameMoving/threads:2/mode:0/width:480"},
                        {"iterations", 40},
                        {"real_time", 83.0},
                        {"cpu_time", 82.5},
                        {"time_unit", "ms"},
                        {"frames_per_s", 12.05},
                        {"pixels", 129600}}}}};
  const std::string md = bench_markdown(results, "", {}, "/nonexistent", "x");
  EXPECT_NE(md.find("## `silva view` frames"), std::string::npos) << md;
  EXPECT_NE(md.find("--benchmark_filter='BM_ViewFrameMoving/threads:2'"), std::string::npos) << md;
  EXPECT_NE(md.find("| BM_ViewFrameMoving/threads:2/mode:0/width:480 | 83.000 | ms | frames_per_s=12.05, pixels=1.296e+05 |"),
            std::string::npos)
      << md;
  EXPECT_EQ(md.find("iterations="), std::string::npos) << "Google Benchmark's own fields are not counters:\n" << md;
}

TEST(BenchPeers, OutcomeTellsNotBuiltFromDidNotRun) {
  EXPECT_EQ(program_outcome({{"real_time", 3.0}}).status, "ran");
  const ProgramOutcome failed = program_outcome({{"error_occurred", true}, {"error_message", "llvmpipe disagrees"}});
  EXPECT_EQ(failed.status, "did not run");
  EXPECT_EQ(failed.note, "did not run: llvmpipe disagrees");
  EXPECT_EQ(program_outcome({{"real_time", 0.0}}).status, "did not run") << "no error but no time is not a figure";
  const std::string no_egl = "built without the llvmpipe peer (Debian: libegl-dev)";
  EXPECT_EQ(program_outcome({{"error_occurred", true}, {"error_message", no_egl}}).note,
            "not built: install libegl-dev and rebuild (built without the llvmpipe peer)");
}

TEST(BenchProcess, ReportsTheBuildAndTheWholeProcessSideBySide) {
  const nlohmann::json process = {{"ran", true},  {"command", "silva world --json"},
                                  {"runs", 3},     {"wall_s", 1.61},
                                  {"min_s", 1.6},  {"max_s", 1.7},
                                  {"cpu_s", 2.6}};
  nlohmann::json results = results_with(nlohmann::json{{"ran", false}, {"note", "not run"}});
  const nlohmann::json g = generation_and_process(results, process);
  EXPECT_DOUBLE_EQ(g["build_s"].get<double>(), 0.84);
  EXPECT_DOUBLE_EQ(g["process_wall_s"].get<double>(), 1.61);
  EXPECT_NEAR(g["difference_s"].get<double>(), 0.77, 1e-12);
  EXPECT_FALSE(g["explanation"].get<std::string>().empty());
  results["generation_process"] = g;
  const std::string md = bench_markdown(results, "", {}, "/nonexistent", "x");
  EXPECT_NE(md.find("| build in the harness (Table 5.1 at 5 %: world context + build) | 0.84 |"), std::string::npos)
      << md;
  EXPECT_NE(md.find("| `silva world` as a whole process (median of 3) | 1.61 |"), std::string::npos) << md;
  EXPECT_NE(md.find("takes 0.77 s more than the build: process start, loading the config, ontology and asset library"),
            std::string::npos)
      << md;
  results["generation_process"] = generation_and_process(results, nlohmann::json{{"ran", true}, {"wall_s", 0.5}});
  const std::string faster = bench_markdown(results, "", {}, "/nonexistent", "x");
  EXPECT_NE(faster.find("took 0.34 s less than the build figure"), std::string::npos) << faster;
}

TEST(BenchProcess, AProcessThatDidNotRunHasNoFigure) {
  const nlohmann::json g = generation_and_process(results_with(nullptr), time_whole_process("", BenchPlan{}, 1));
  EXPECT_TRUE(g["process_wall_s"].is_null());
  EXPECT_TRUE(g["difference_s"].is_null());
  EXPECT_NE(generation_process_markdown(g).find("not run: the harness is not running as the silva binary"),
            std::string::npos);
  const nlohmann::json failed = time_whole_process("/bin/false", BenchPlan{}, 1, 1);
  EXPECT_FALSE(failed["ran"].get<bool>());
  EXPECT_NE(failed["note"].get<std::string>().find("failed"), std::string::npos);
}

TEST(BenchProcess, TimesSilvaWorldOfATinyWorldAsAChildProcess) {
  BenchPlan plan;
  plan.overrides = {"world.extent=128", "world.render_distance=32", "trail.control_points=6"};
  const auto args = whole_process_args(plan, 1);
  EXPECT_EQ(args.front(), "world");
  EXPECT_NE(std::find(args.begin(), args.end(), "world.extent=128"), args.end());
  const nlohmann::json p = time_whole_process(SILVA_BINARY, plan, 1, 1);
  ASSERT_TRUE(p["ran"].get<bool>()) << p.dump();
  EXPECT_GT(p["wall_s"].get<double>(), 0.0);
  EXPECT_GE(p["cpu_s"].get<double>(), 0.0);
  EXPECT_EQ(p["runs"].get<int>(), 1);
}

}  // namespace
}  // namespace silva::bench
