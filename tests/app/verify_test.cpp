// `silva verify`: passes on a fresh dataset, fails (exit 4) on a dataset whose depth or classes were
// tampered with, and refuses bad input (exit 2) without touching the dataset.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>

#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "io/atomic_file.hpp"
#include "io/exr_writer.hpp"
#include "silva_process.hpp"
#include "tests/common/scratch_dirs.hpp"

namespace silva::test {
namespace {

namespace fs = std::filesystem;

/// 160x90, one autopilot point and one random pose, every label type, normals, depth PNG and EXR, and a
/// short-range LiDAR (so the frame streams few chunks). Full detail (render.lod = false); the test with
/// LOD turns it on.
constexpr const char* kConfig = R"(
[output]
resolution = "160x90"
types = ["semantic", "instance", "depth", "depth_exr", "normal", "lidar"]
[captures]
autopilot_points = 1
autopilot_yaws = [0]
random_count = 1
[world]
extent = 128
render_distance = 48
[trail]
control_points = 6
[camera]
far = 40
[render]
lod = false
[lidar]
preset = "short"
[lidar.presets.short]
channels = 16
elevation_min_deg = -15
elevation_max_deg = 15
columns = 512
max_range = 30
)";

/// The dataset every test starts from: generated once per test program.
class Verify : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    root_ = fs::path(::testing::TempDir()) / ("silva_verify_" + std::to_string(::getpid()));
    fs::remove_all(root_);
    fs::create_directories(root_);
    remove_when_passed(root_);
    std::ofstream(root_ / "verify.toml") << kConfig;
    const ProcessResult r = run_silva(
        {"generate", "--config", (root_ / "verify.toml").string(), "--seed", "77", "--out", (root_ / "out").string()},
        root_);
    ASSERT_EQ(r.code, 0) << r.err;
  }

  /// A copy of the dataset of its own, for a test to edit.
  fs::path copy_dataset() {
    const fs::path dir = fresh_test_dir() / "0000000077";
    fs::copy(root_ / "out" / "0000000077", dir, fs::copy_options::recursive);
    return dir;
  }

  /// `silva verify dir args... --json`.
  ProcessResult verify(const fs::path& dir, std::vector<std::string> args = {}) {
    args.insert(args.begin(), {"verify", dir.string(), "--sample", "1", "--json"});
    return run_silva(args, dir.parent_path());
  }

  static fs::path root_;
};

fs::path Verify::root_;

/// The summary object verify printed on stdout.
nlohmann::json summary(const ProcessResult& r) { return nlohmann::json::parse(r.out); }

TEST_F(Verify, PassesOnAFreshDatasetAndTouchesNothingElse) {
  const fs::path dir = copy_dataset();
  const auto before = folder_files(dir, /*with_run_records=*/true);
  const ProcessResult r = verify(dir);
  ASSERT_EQ(r.code, 0) << r.err << r.out;
  const nlohmann::json s = summary(r);
  EXPECT_TRUE(s["ok"].get<bool>());
  EXPECT_EQ(s["frames_checked"], 2);
  EXPECT_EQ(s["pixels"], 2 * 160 * 90);
  EXPECT_GE(s["class"]["interior"]["agreement"].get<double>(), 0.999);
  EXPECT_GE(s["depth"]["within_tolerance"].get<double>(), 0.999);
  EXPECT_GE(s["instance"]["interior_agreement"].get<double>(), 0.999);
  EXPECT_LT(s["normal"]["angle_error_deg"]["p50"].get<double>(), 1.0);
  EXPECT_GT(s["lidar"]["compared"].get<uint64_t>(), 100u);
  // About 170 points: a beam may hit a nettle stem or stalk nearer than the 160x90 camera resolves, so two
  // or three may disagree; more than 2 % would be a labelling fault.
  EXPECT_GE(s["lidar"]["class_agreement"].get<double>(), 0.98);
  EXPECT_LT(s["lidar"]["range_error_m"]["p50"].get<double>(), 0.05);
  // verify.json is the summary less what varies; VERIFY.md states the verdict.
  const nlohmann::json file = nlohmann::json::parse(read_file(dir / "verify.json"));
  EXPECT_EQ(file["class"], s["class"]);
  EXPECT_FALSE(file.contains("seconds"));
  EXPECT_NE(read_file(dir / "VERIFY.md").find("**Verdict: PASS**"), std::string::npos);
  auto after = folder_files(dir, /*with_run_records=*/true);
  after.erase("verify.json");
  after.erase("VERIFY.md");
  EXPECT_EQ(file_differences(before, after), "");
  // The same dataset gives the same certificate (a seeded sample of frames and pixels).
  const std::string first = read_file(dir / "verify.json");
  ASSERT_EQ(run_silva({"verify", dir.string(), "--sample", "0.5", "--threads", "1", "--quiet"}, dir.parent_path()).code, 0);
  const std::string half = read_file(dir / "verify.json");
  ASSERT_EQ(run_silva({"verify", dir.string(), "--sample", "0.5", "--threads", "2", "--quiet"}, dir.parent_path()).code, 0);
  EXPECT_EQ(read_file(dir / "verify.json"), half);
  EXPECT_NE(half, first);
  // A bare folder name from its parent folder works as well (the world's output.dir is its absolute parent).
  const fs::path cwd = fs::current_path();
  fs::current_path(dir.parent_path());  // the child starts there
  const ProcessResult bare = run_silva({"verify", dir.filename().string(), "--sample", "0.5", "--quiet"}, dir.parent_path());
  fs::current_path(cwd);
  EXPECT_EQ(bare.code, 0) << bare.err;
  EXPECT_EQ(read_file(dir / "verify.json"), half);
}

TEST_F(Verify, DepthShiftedByOnePercentInOneFrameFails) {
  const fs::path dir = copy_dataset();
  const fs::path exr = dir / "random" / "depth_exr" / "000000.exr";
  setenv("OPENCV_IO_ENABLE_OPENEXR", "1", 1);
  const cv::Mat depth = cv::imread(exr.string(), cv::IMREAD_UNCHANGED);
  ASSERT_EQ(depth.type(), CV_32FC1);
  std::vector<float> shifted(depth.ptr<float>(), depth.ptr<float>() + depth.total());
  for (float& z : shifted) z *= 1.01f;
  io::write_file_atomic(exr, io::encode_exr_y(shifted, depth.cols, depth.rows));
  const ProcessResult r = verify(dir);
  ASSERT_EQ(r.code, 4) << r.err << r.out;
  const nlohmann::json s = summary(r);
  EXPECT_FALSE(s["verdict"]["depth"].get<bool>());
  EXPECT_TRUE(s["verdict"]["class_interior"].get<bool>());
  EXPECT_LT(s["depth"]["within_tolerance"].get<double>(), 0.7);
  EXPECT_NE(read_file(dir / "VERIFY.md").find("**Verdict: FAIL**"), std::string::npos);
  // A tolerance above the shift lets it pass: the check measures the depth, not the files' bytes.
  EXPECT_EQ(verify(dir, {"--depth-tolerance", "1.5"}).code, 0);
}

TEST_F(Verify, TwoClassesSwappedInOneSemanticImageFail) {
  const fs::path dir = copy_dataset();
  const fs::path png = dir / "autopilot" / "semantic" / "000000.png";
  cv::Mat semantic = cv::imread(png.string(), cv::IMREAD_UNCHANGED);
  ASSERT_EQ(semantic.type(), CV_8UC1);
  // Swap the two most common classes of the frame.
  std::array<int, 256> count{};
  for (int i = 0; i < int(semantic.total()); ++i) ++count[semantic.data[i]];
  std::array<int, 256> order;
  for (int c = 0; c < 256; ++c) order[size_t(c)] = c;
  std::sort(order.begin(), order.end(), [&](int a, int b) { return count[size_t(a)] > count[size_t(b)]; });
  const uint8_t a = uint8_t(order[0]), b = uint8_t(order[1]);
  ASSERT_GT(count[b], 500);
  for (int i = 0; i < int(semantic.total()); ++i)
    semantic.data[i] = semantic.data[i] == a ? b : semantic.data[i] == b ? a : semantic.data[i];
  ASSERT_TRUE(cv::imwrite(png.string(), semantic));
  const ProcessResult r = verify(dir);
  ASSERT_EQ(r.code, 4) << r.err << r.out;
  const nlohmann::json s = summary(r);
  EXPECT_FALSE(s["verdict"]["class_interior"].get<bool>());
  EXPECT_LT(s["class"]["interior"]["agreement"].get<double>(), 0.9);
  bool swapped = false;
  for (const auto& e : s["class"]["interior_confusion"])
    swapped = swapped || (e["file_class"] == b && e["ray_class"] == a && e["pixels"].get<int>() > 100);
  EXPECT_TRUE(swapped) << s["class"]["interior_confusion"].dump();
}

TEST_F(Verify, WithLodItCastsTheLevelsDrawnAndFullDetailMeasuresTheirError) {
  // The same dataset rendered with LOD (the default): verify meets each instance at the level the
  // rasteriser drew for the frame and passes; --full-detail counts the coarse levels' depth error.
  const fs::path root = fresh_test_dir();
  std::string config = kConfig;
  config.replace(config.find("lod = false"), 11, "lod = true");
  std::ofstream(root / "lod.toml") << config;
  ASSERT_EQ(run_silva({"generate", "--config", (root / "lod.toml").string(), "--seed", "77", "--out",
                       (root / "out").string(), "--quiet"},
                      root)
                .code,
            0);
  const fs::path dir = root / "out" / "0000000077";
  const ProcessResult drawn = verify(dir);
  ASSERT_EQ(drawn.code, 0) << drawn.err << drawn.out;
  const nlohmann::json as_drawn = summary(drawn);
  EXPECT_EQ(as_drawn["geometry"], "as_drawn");
  EXPECT_NE(read_file(dir / "VERIFY.md").find("at the level the rasteriser drew"), std::string::npos);
  const ProcessResult full = verify(dir, {"--full-detail", "--min-depth", "0"});
  ASSERT_EQ(full.code, 0) << full.err << full.out;
  const nlohmann::json full_detail = summary(full);
  EXPECT_EQ(full_detail["geometry"], "full_detail");
  EXPECT_EQ(full_detail["class"]["interior"]["agreement"], as_drawn["class"]["interior"]["agreement"]);
  EXPECT_LT(full_detail["depth"]["within_tolerance"].get<double>(), as_drawn["depth"]["within_tolerance"].get<double>());
}

/// Exit 2 with one line naming `expect`, and nothing written into the dataset.
void expect_refused(const ProcessResult& r, const fs::path& dir, const std::string& expect) {
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find(expect), std::string::npos) << r.err;
  EXPECT_EQ(lines_of(r.err).size(), 1u) << r.err;
  EXPECT_FALSE(fs::exists(dir / "verify.json"));
  EXPECT_FALSE(fs::exists(dir / "VERIFY.md"));
}

TEST_F(Verify, BadInputIsRefused) {
  const fs::path dir = copy_dataset();
  const fs::path manifest = dir / "manifest.json";
  const std::string text = read_file(manifest);
  fs::remove(manifest);
  expect_refused(run_silva({"verify", dir.string()}, dir.parent_path()), dir, "no manifest.json");
  nlohmann::json other = nlohmann::json::parse(text);
  other["silva_version"] = "0.0.1";
  std::ofstream(manifest) << other.dump(2);
  expect_refused(run_silva({"verify", dir.string()}, dir.parent_path()), dir, "written by Silva 0.0.1");
  std::ofstream(manifest) << text;
  fs::remove(dir / "random" / "semantic" / "000000.png");
  expect_refused(run_silva({"verify", dir.string()}, dir.parent_path()), dir, "semantic/000000.png: missing");
  expect_refused(run_silva({"verify", dir.string(), "--frobnicate"}, dir.parent_path()), dir, "--frobnicate");
  expect_refused(run_silva({"verify", dir.string(), "--sample", "0"}, dir.parent_path()), dir, "--sample");
  expect_refused(run_silva({"verify", (dir / "random").string()}, dir.parent_path()), dir / "random",
                 "not a Silva dataset");
}

}  // namespace
}  // namespace silva::test
