// LiDAR presets as data: configs/lidar.toml, user tables, and the errors of bad ones.
#include "pipeline/config/lidar_config.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "pipeline/config/data_path.hpp"
#include "core/error.hpp"
#include "silva_process.hpp"
#include "app/cli/pipeline_names.hpp"

namespace silva::app {
namespace {

/// The presets of configs/lidar.toml.
std::map<std::string, raycast::LidarPreset> shipped() {
  const toml::table file = toml::parse_file(data_path("configs/lidar.toml").string());
  return parse_lidar_presets(*file["lidar"]["presets"].as_table(), "lidar.toml");
}

/// The InputError message of parsing `text` (a [lidar.presets.<name>] file) over the shipped presets.
std::string error_of(const std::string& text) {
  try {
    const toml::table t = toml::parse(text);
    parse_lidar_presets(*t["lidar"]["presets"].as_table(), "user.toml", shipped());
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(LidarConfig, ShippedPresetsHaveTheirBeams) {
  const auto p = shipped();
  for (const char* name : {"vlp16", "hdl32e", "hdl64e", "os1_64", "os1_128"}) ASSERT_TRUE(p.count(name)) << name;
  EXPECT_EQ(p.at("vlp16").elevations_deg.size(), 16u);
  EXPECT_DOUBLE_EQ(p.at("vlp16").elevations_deg.front(), -15.0);
  EXPECT_DOUBLE_EQ(p.at("vlp16").elevations_deg[1], -13.0);
  EXPECT_DOUBLE_EQ(p.at("vlp16").elevations_deg.back(), 15.0);
  EXPECT_EQ(p.at("vlp16").columns, 1800);
  EXPECT_EQ(p.at("hdl32e").elevations_deg.size(), 32u);
  const auto& hdl64 = p.at("hdl64e").elevations_deg;
  ASSERT_EQ(hdl64.size(), 64u);
  EXPECT_NEAR(hdl64.front(), -24.333, 1e-3);
  EXPECT_NEAR(hdl64.back(), 2.0, 1e-9);
  EXPECT_NEAR(hdl64[63] - hdl64[62], 1.0 / 3.0, 1e-3);  // upper block: 1/3 degree
  EXPECT_NEAR(hdl64[1] - hdl64[0], 0.5, 1e-3);           // lower block: 1/2 degree
  EXPECT_EQ(p.at("os1_64").elevations_deg.size(), 64u);
  EXPECT_EQ(p.at("os1_64").columns, 2048);
  EXPECT_EQ(p.at("os1_128").elevations_deg.size(), 128u);
}

TEST(LidarConfig, UserTablesOverlayAPresetOrStartFromVlp16) {
  const toml::table t = toml::parse(R"(
[lidar.presets.vlp16]
max_range = 50
[lidar.presets.mine]
elevations_deg = [-10, 0, 10]
columns = 90
)");
  const auto p = parse_lidar_presets(*t["lidar"]["presets"].as_table(), "user.toml", shipped());
  EXPECT_EQ(p.at("vlp16").max_range, 50);
  EXPECT_EQ(p.at("vlp16").elevations_deg.size(), 16u);
  EXPECT_EQ(p.at("mine").elevations_deg, (std::vector<double>{-10, 0, 10}));
  EXPECT_EQ(p.at("mine").columns, 90);
  EXPECT_EQ(p.at("mine").rotation_hz, 10);
  EXPECT_EQ(p.at("hdl64e").elevations_deg.size(), 64u);
}

TEST(LidarConfig, OneBeamKeyChangesOnlyItselfKeepingThePresetsOtherBeams) {
  const toml::table t = toml::parse(R"(
[lidar.presets.vlp16]
channels = 31
[lidar.presets.os1_64]
elevation_max_deg = 0
)");
  const auto p = parse_lidar_presets(*t["lidar"]["presets"].as_table(), "user.toml", shipped());
  const std::vector<double>& vlp = p.at("vlp16").elevations_deg;  // vlp16: -15 ... 15
  ASSERT_EQ(vlp.size(), 31u);
  EXPECT_EQ(vlp.front(), -15);
  EXPECT_EQ(vlp.back(), 15);
  EXPECT_DOUBLE_EQ(vlp[1] - vlp[0], 1.0);
  const std::vector<double>& os1 = p.at("os1_64").elevations_deg;
  ASSERT_EQ(os1.size(), 64u);
  EXPECT_EQ(os1.front(), shipped().at("os1_64").elevations_deg.front());
  EXPECT_EQ(os1.back(), 0);
}

TEST(LidarConfig, MalformedTablesAreOneClearLine) {
  const std::string unknown = error_of("[lidar.presets.x]\nbeams = 3\n");
  EXPECT_NE(unknown.find("user.toml:2:9: unknown key 'lidar.presets.x.beams' (allowed: channels,"), std::string::npos)
      << unknown;
  EXPECT_NE(error_of("[lidar.presets.x]\ncolumns = \"many\"\n").find("lidar.presets.x.columns must be a whole number"),
            std::string::npos);
  EXPECT_NE(error_of("[lidar.presets.x]\ndropout = 2\n").find("lidar.presets.x.dropout = 2 is out of range, allowed 0 .. 0.99"),
            std::string::npos);
  EXPECT_NE(error_of("[lidar.presets.x]\nelevations_deg = [1, -1]\n").find("must be ascending"), std::string::npos);
  std::string beams = "[lidar.presets.x]\nelevations_deg = [";  // 1 025 beams: one over the channels limit
  for (int i = 0; i <= 1024; ++i) beams += (i ? ", " : "") + std::to_string(-60.0 + i * 0.1);
  EXPECT_NE(error_of(beams + "]\n").find("1 to 1024 elevations"), std::string::npos);
  EXPECT_NE(error_of("[lidar.presets.x]\nelevations_deg = [-1, 1]\nchannels = 3\n").find("lists 2 beams"),
            std::string::npos);
  EXPECT_EQ(error_of("[lidar.presets.x]\nchannels = 8\n"), "") << "one beam key keeps vlp16's other beams";
  EXPECT_NE(error_of("[lidar.presets.x]\nmin_range = 200\n").find("min_range must be below max_range"), std::string::npos);
  EXPECT_NE(error_of("[lidar.presets]\nx = 3\n").find("lidar.presets.x must be a table"), std::string::npos);
  for (const std::string& e : {unknown, error_of("[lidar.presets.x]\ndropout = 2\n")}) EXPECT_EQ(e.find('\n'), std::string::npos);
}

TEST(LidarConfig, CliRejectsAnUnknownPresetAndABadTableWithExitTwo) {
  namespace fs = std::filesystem;
  const fs::path dir = test::fresh_test_dir();
  std::vector<std::string> args = test::tiny_run_args(dir / "out", 3, R"(["semantic","lidar"])");
  args.insert(args.end(), {"--set", "lidar.preset=vlp17"});
  const test::ProcessResult r = test::run_silva(args, dir);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(test::lines_of(r.err).size(), 1u) << r.err;
  EXPECT_NE(r.err.find("lidar.preset = \"vlp17\" is not a LiDAR preset (allowed: hdl32e, hdl64e, os1_128, os1_64, vlp16"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(dir / "out" / "0000000003" / "manifest.json"));

  std::ofstream(dir / "bad.toml") << "[lidar.presets.vlp16]\nchannels = \"sixteen\"\n";
  const test::ProcessResult bad = test::run_silva({"generate", "--config", (dir / "bad.toml").string(), "--seed", "3",
                                                   "--out", (dir / "out2").string()}, dir);
  EXPECT_EQ(bad.code, 2);
  EXPECT_EQ(test::lines_of(bad.err).size(), 1u) << bad.err;
  EXPECT_NE(bad.err.find("lidar.presets.vlp16.channels must be a whole number"), std::string::npos) << bad.err;
}

TEST(LidarConfig, ValidateRefusesWhatGenerateRefuses) {
  namespace fs = std::filesystem;
  const fs::path dir = test::fresh_test_dir();
  std::ofstream(dir / "ranges.toml") << "[lidar.presets.vlp16]\nmin_range = 50\nmax_range = 10\n";
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"validate", "--set", "lidar.preset=vlp17"},
        std::vector<std::string>{"validate", "--set", "lidar.preset="},
        std::vector<std::string>{"validate", "--config", (dir / "ranges.toml").string()}}) {
    const test::ProcessResult r = test::run_silva(args, dir);
    EXPECT_EQ(r.code, 2) << args.back() << "\n" << r.err;
    EXPECT_EQ(test::lines_of(r.err).size(), 1u) << r.err;
  }
}

}  // namespace
}  // namespace silva::app
