// lighting.randomize and lighting.exposure = "auto" through `silva generate`: the draws are the same
// for any thread count, differ between frames, stay within the configured ranges and are read back
// from each camera file; with randomisation off (the default) the RGB keeps its bytes; bad ranges
// are one line and exit 2.
#include <gtest/gtest.h>

#include <set>

#include <nlohmann/json.hpp>

#include "io/camera_json.hpp"
#include "silva_process.hpp"

namespace silva::test {
namespace {

namespace fs = std::filesystem;

/// A tiny random-only run of `frames` frames with rgb and semantic, plus `extra` --set overrides.
std::vector<std::string> run_args(const fs::path& out, int frames, const std::vector<std::string>& extra) {
  std::vector<std::string> args = tiny_run_args(out, 27182818, R"(["rgb","semantic"])");
  args.insert(args.end(), {"--set", R"(captures.sequences=["random"])", "--set",
                           "captures.random_count=" + std::to_string(frames), "--set", "output.resolution=160x90"});
  for (const std::string& e : extra) args.insert(args.end(), {"--set", e});
  return args;
}

const std::vector<std::string> kRandomize = {
    "lighting.randomize.enabled=true", "lighting.randomize.sun_elevation_deg=[20, 60]",
    "lighting.randomize.cloud_cover=[0.1, 0.5]", "lighting.randomize.white_balance_k=[5000, 8000]",
    R"(lighting.randomize.weathers=["clear","mist"])", "lighting.randomize.weather_weights=[1, 1]"};

TEST(GenerateRandomize, DrawsArePerFrameInRangeRecordedAndTheSameForAnyThreadCount) {
  const fs::path dir = fresh_test_dir();
  std::map<std::string, std::string> files[2];
  for (const int threads : {1, 3}) {
    const fs::path out = dir / ("t" + std::to_string(threads));
    std::vector<std::string> args = run_args(out, 6, kRandomize);
    args.insert(args.end(), {"--threads", std::to_string(threads)});
    const ProcessResult r = run_silva(args, dir);
    ASSERT_EQ(r.code, 0) << r.err;
    files[threads == 1 ? 0 : 1] = folder_files(out / "0027182818");
  }
  EXPECT_EQ(file_differences(files[0], files[1]), "");
  std::set<double> elevations, white_balances;
  std::set<std::string> rgb;
  for (int frame = 0; frame < 6; ++frame) {
    char name[32];
    std::snprintf(name, sizeof name, "%06d", frame);
    const fs::path seq = dir / "t1" / "0027182818" / "random";
    const io::CameraRecord c = io::read_camera_json(seq / "camera" / (std::string(name) + ".json"));
    ASSERT_TRUE(c.lighting.has_value()) << frame;
    const io::LightingRecord& l = *c.lighting;
    EXPECT_TRUE(l.randomized);
    EXPECT_EQ(l.time_of_day, "day");
    EXPECT_TRUE(l.weather == "clear" || l.weather == "mist") << l.weather;
    EXPECT_GE(l.sun_elevation_deg, 20.0);
    EXPECT_LE(l.sun_elevation_deg, 60.0);
    EXPECT_GE(l.sun_azimuth_deg, 0.0);  // the default range
    EXPECT_LE(l.sun_azimuth_deg, 360.0);
    EXPECT_GE(l.cloud_cover, 0.1 - 1e-6);
    EXPECT_LE(l.cloud_cover, 0.5 + 1e-6);
    EXPECT_GE(l.fog_density_scale, 0.5 - 1e-6);
    EXPECT_LE(l.fog_density_scale, 2.0 + 1e-6);
    EXPECT_GE(l.white_balance_k, 5000.0);
    EXPECT_LE(l.white_balance_k, 8000.0);
    EXPECT_GE(l.exposure_compensation_ev, -0.5 - 1e-6);
    EXPECT_LE(l.exposure_compensation_ev, 0.5 + 1e-6);
    EXPECT_EQ(l.exposure, "preset");
    ASSERT_TRUE(l.ev100.has_value());
    EXPECT_NEAR(*l.ev100, 13.5 - l.exposure_compensation_ev, 1e-5);  // the day preset's ev100
    elevations.insert(l.sun_elevation_deg);
    white_balances.insert(l.white_balance_k);
    rgb.insert(read_file(seq / "rgb" / (std::string(name) + ".png")));
  }
  EXPECT_EQ(elevations.size(), 6u);
  EXPECT_EQ(white_balances.size(), 6u);
  EXPECT_EQ(rgb.size(), 6u);
}

TEST(GenerateRandomize, OffByDefaultAndAPointRangeAtThePresetKeepsTheBytes) {
  const fs::path dir = fresh_test_dir();
  const ProcessResult plain = run_silva(run_args(dir / "plain", 3, {}), dir);
  ASSERT_EQ(plain.code, 0) << plain.err;
  // Every range at the day preset's own value, clear weather, neutral white balance, no offset.
  const ProcessResult pinned = run_silva(
      run_args(dir / "pinned", 3,
               {"lighting.randomize.enabled=true", "lighting.randomize.sun_elevation_deg=[55, 55]",
                "lighting.randomize.sun_azimuth_deg=[135, 135]", "lighting.randomize.cloud_cover=[0.35, 0.35]",
                "lighting.randomize.fog_density_scale=[1, 1]", "lighting.randomize.exposure_compensation_ev=[0, 0]",
                "lighting.randomize.white_balance_k=[6504, 6504]", R"(lighting.randomize.weathers=["clear"])",
                "lighting.randomize.weather_weights=[1]"}),
      dir);
  ASSERT_EQ(pinned.code, 0) << pinned.err;
  const fs::path a = dir / "plain" / "0027182818" / "random", b = dir / "pinned" / "0027182818" / "random";
  EXPECT_EQ(read_file(a / "camera" / "000001.json").find("\"lighting\""), std::string::npos);
  EXPECT_NE(read_file(b / "camera" / "000001.json").find("\"lighting\""), std::string::npos);
  for (const char* type : {"rgb", "semantic"})
    EXPECT_EQ(file_differences(folder_files(a / type), folder_files(b / type)), "") << type;
}

TEST(GenerateRandomize, AutoExposureIsRecordedWithTheMeteredEv100) {
  const fs::path dir = fresh_test_dir();
  const ProcessResult r =
      run_silva(run_args(dir / "auto", 2, {"lighting.exposure=auto", "lighting.time_of_day=night"}), dir);
  ASSERT_EQ(r.code, 0) << r.err;
  const io::CameraRecord c = io::read_camera_json(dir / "auto" / "0027182818" / "random" / "camera" / "000000.json");
  ASSERT_TRUE(c.lighting.has_value());
  EXPECT_FALSE(c.lighting->randomized);
  EXPECT_EQ(c.lighting->exposure, "auto");
  EXPECT_EQ(c.lighting->time_of_day, "night");
  ASSERT_TRUE(c.lighting->ev100.has_value());
  EXPECT_LT(*c.lighting->ev100, 3.0);  // metered for moonlight, far below a day's 15
  EXPECT_GT(*c.lighting->ev100, -10.0);
}

TEST(GenerateRandomize, BadRangesAreOneLineAndExitTwo) {
  const fs::path dir = fresh_test_dir();
  const std::pair<std::string, std::string> cases[] = {
      {"lighting.randomize.sun_elevation_deg=[60, 20]", "lighting.randomize.sun_elevation_deg = [60, 20] must have min <= max"},
      {"lighting.randomize.cloud_cover=[0.5]", "lighting.randomize.cloud_cover must list 2 numbers [min, max], got 1"},
      {"lighting.randomize.cloud_cover=[0, 2]", "lighting.randomize.cloud_cover"},
      {R"(lighting.randomize.weathers=["clear","fogg"])", "lighting.randomize.weathers names \"fogg\""},
      {"lighting.randomize.weather_weights=[1, 2]", "lighting.randomize.weather_weights must list one weight per name"},
      {"lighting.randomize.weather_weights=[0, 0, 0, 0]", "at least one weight above 0"},
      {"lighting.exposure=manual", "lighting.exposure"},
  };
  for (const auto& [set, message] : cases) {
    const ProcessResult r = run_silva({"validate", "--set", set}, dir);
    EXPECT_EQ(r.code, 2) << set;
    EXPECT_NE(r.err.find(message), std::string::npos) << set << ": " << r.err;
    EXPECT_EQ(lines_of(r.err).size(), 1u) << r.err;
  }
  const ProcessResult print = run_silva({"validate", "--print"}, dir);
  ASSERT_EQ(print.code, 0) << print.err;
  for (const char* key : {"randomize.enabled = false", "randomize.sun_elevation_deg = [15.0, 70.0]", "exposure = \"preset\"",
                          "randomize.weathers = [\"clear\", \"overcast\", \"mist\", \"rain\"]"})
    EXPECT_NE(print.out.find(key), std::string::npos) << key;
}

}  // namespace
}  // namespace silva::test
