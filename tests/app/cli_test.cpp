#include "app/cli/cli.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "pipeline/config/config_loader.hpp"
#include "tests/common/config_equal.hpp"
#include "app/cli/pipeline_names.hpp"

namespace silva::app {
namespace {

namespace fs = std::filesystem;

/// What one in-process `silva ...` run printed and returned.
struct CliResult {
  int code = -1;
  std::string out;
  std::string err;
};

CliResult run(std::vector<std::string> args) {
  args.insert(args.begin(), "silva");
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  ::testing::internal::CaptureStdout();
  ::testing::internal::CaptureStderr();
  CliResult result;
  result.code = run_cli(static_cast<int>(argv.size()), argv.data());
  result.err = ::testing::internal::GetCapturedStderr();
  result.out = ::testing::internal::GetCapturedStdout();
  return result;
}

class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(::testing::TempDir()) /
           ("silva_cli_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    out_ = (dir_ / "out").string();
  }
  void TearDown() override { fs::remove_all(dir_); }

  /// Writes a config file into the test folder and returns its path.
  std::string write_config(const std::string& text) {
    const fs::path path = dir_ / "config.toml";
    std::ofstream(path) << text;
    return path.string();
  }

  /// Expects exit `code`, exactly `message` as the one stderr line, and no output folder.
  void expect_bad(const CliResult& r, int code, const std::string& message) {
    EXPECT_EQ(r.code, code);
    EXPECT_EQ(r.err, "silva: error: " + message + "\n");
    EXPECT_FALSE(fs::exists(out_)) << "bad input must write nothing";
  }

  fs::path dir_;
  std::string out_;
};

TEST_F(Cli, UnknownKeyInConfigSuggestsClosest) {
  const std::string config = write_config("[camera]\nfovdeg = 75\n");
  expect_bad(run({"generate", "--config", config, "--out", out_}), 2,
             config + ":2:10: unknown key 'camera.fovdeg' (did you mean 'camera.fov_deg'?)");
}

TEST_F(Cli, WrongTypeNamesKeyExpectedAndGot) {
  const std::string config = write_config("[trail]\nenabled = \"yes\"\n");
  expect_bad(run({"generate", "--config", config, "--out", out_}), 2,
             config + ":2:11: trail.enabled must be a boolean (true or false), got a string (\"yes\")");
  expect_bad(run({"generate", "--out", out_, "--set", "camera.fov_deg=wide"}), 2,
             "--set camera.fov_deg=wide: camera.fov_deg must be a number, got 'wide'");
}

TEST_F(Cli, OutOfRangeSaysAllowedRange) {
  expect_bad(run({"generate", "--out", out_, "--set", "vegetation.density=30"}), 2,
             "--set vegetation.density=30: vegetation.density = 30 is out of range (allowed: 1 to 25)");
  const std::string config = write_config("[output]\nresolution = \"9000x100\"\n");
  expect_bad(run({"generate", "--config", config, "--out", out_}), 2,
             config + ":2:14: output.resolution = \"9000x100\" is out of range (allowed: \"WxH\", each 16 to 8192)");
}

TEST_F(Cli, MissingConfigFile) {
  const std::string missing = (dir_ / "nope.toml").string();
  expect_bad(run({"generate", "--config", missing, "--out", out_}), 2,
             "config file '" + missing + "' not found");
}

TEST_F(Cli, UnparsableConfigNamesLineAndColumn) {
  const std::string config = write_config("seed = 1\n[camera\nnear = 1\n");
  const CliResult r = run({"generate", "--config", config, "--out", out_});
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err.rfind("silva: error: " + config + ":2:", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("invalid TOML"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line";
  EXPECT_FALSE(fs::exists(out_));
}

TEST_F(Cli, BadSetAssignments) {
  expect_bad(run({"generate", "--out", out_, "--set", "seed"}), 2,
             "--set seed: expected key=value, e.g. --set camera.fov_deg=75");
  expect_bad(run({"generate", "--out", out_, "--set", "vegetation.densty=5"}), 2,
             "--set vegetation.densty=5: unknown key 'vegetation.densty' (did you mean 'vegetation.density'?)");
  expect_bad(run({"generate", "--out", out_, "--set", "vegetation.season=wintr"}), 2,
             "--set vegetation.season=wintr: vegetation.season: \"wintr\" is not allowed (one of summer, autumn, "
             "winter, spring, early_spring; did you mean \"winter\"?)");
}

TEST_F(Cli, CrossKeyAndFlagErrors) {
  expect_bad(run({"generate", "--out", out_, "--set", "camera.near=200"}), 2,
             "config: camera.near = 200 must be less than camera.far = 150");
  expect_bad(run({"generate", "--out", out_, "--seed", "1", "--shard", "4/4"}), 2,
             "--shard 4/4: expected i/N with 0 <= i < N, e.g. --shard 0/4");
  expect_bad(run({"generate", "--out", out_, "--shard", "0/2"}), 2,
             "--shard 0/2 needs an explicit seed (--seed N or seed in the config)");
  expect_bad(run({"world", "--seed", "1", "--export", (dir_ / "w.gltf").string()}), 2,
             "--export " + (dir_ / "w.gltf").string() + ": the export is binary glTF, name it FILE.glb");
  expect_bad(run({"merge", out_}), 2,
             "merge: '" + out_ + "' is not a run folder (expected <output.dir>/<seed>/)");
}

TEST_F(Cli, CommandLineParseErrorsAreBadInput) {
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{}, {"frobnicate"}, {"generate", "--bogus"},
        {"generate", "--threads", "0"}, {"generate", "--resume", "--overwrite"},
        {"world", "--center", "1,2"}, {"world", "--instancing"}}) {
    const CliResult r = run(args);
    EXPECT_EQ(r.code, 2) << ::testing::PrintToString(args);
    EXPECT_EQ(r.err.rfind("silva: error: ", 0), 0u) << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
  }
}

TEST_F(Cli, UnwritableOutputIsIoError) {
  const fs::path file = dir_ / "a_file";
  std::ofstream(file) << "x";
  const std::string out = (file / "out").string();
  const CliResult r = run({"generate", "--seed", "1", "--out", out});
  EXPECT_EQ(r.code, 3);
  EXPECT_EQ(r.err, "silva: error: output folder '" + out + "' cannot be created: '" + file.string() +
                       "' is not a folder\n");
}

TEST_F(Cli, JsonErrorsGoToStdoutToo) {
  const CliResult r = run({"validate", "--json", "--set", "seed=x"});
  EXPECT_EQ(r.code, 2);
  const nlohmann::json summary = nlohmann::json::parse(r.out);
  EXPECT_EQ(summary["ok"], false);
  EXPECT_EQ(summary["exit_code"], 2);
  EXPECT_EQ("silva: error: " + summary["error"].get<std::string>() + "\n", r.err);
}

TEST_F(Cli, ValidateJson) {
  const CliResult r = run({"validate", "--config", SILVA_SOURCE_DIR "/configs/demo.toml", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json summary = nlohmann::json::parse(r.out);
  EXPECT_EQ(summary["ok"], true);
  EXPECT_EQ(summary["config"]["seed"], 1234567890);
  EXPECT_EQ(summary["config"]["output"]["resolution"], "1280x720");
}

TEST_F(Cli, ValidatePrintRoundTrips) {
  const CliResult r = run({"validate", "--config", SILVA_SOURCE_DIR "/configs/demo.toml", "--set",
                           "camera.gain=4", "--set", "lighting.time_of_day=night", "--print"});
  ASSERT_EQ(r.code, 0) << r.err;
  const LoadedConfig printed = parse_config_text(r.out, "printed");
  ConfigSources sources{SILVA_SOURCE_DIR "/configs/demo.toml",
                        {"camera.gain=4", "lighting.time_of_day=night"}, {}, {}};
  EXPECT_EQ(testing::config_differences(printed.config, load_config(sources).config), "") << r.out;
}

TEST_F(Cli, ValidatePrintsTheClockSeedItDrew) {
  const CliResult r = run({"validate", "--print", "--quiet"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  const LoadedConfig printed = parse_config_text(r.out, "printed");
  EXPECT_TRUE(printed.seed_given);
  EXPECT_NE(r.out.find("# The seed was drawn from the clock."), std::string::npos);
}

TEST_F(Cli, VersionJson) {
  const CliResult r = run({"version", "--json"});
  ASSERT_EQ(r.code, 0);
  const nlohmann::json summary = nlohmann::json::parse(r.out);
  EXPECT_EQ(summary["version"], SILVA_VERSION);
  EXPECT_EQ(summary["git_revision"], SILVA_GIT_REV);
  EXPECT_TRUE(summary["simd_targets"].is_array());
  EXPECT_EQ(run({"version"}).out.rfind(std::string("silva ") + SILVA_VERSION, 0), 0u);
}

TEST_F(Cli, HelpForEveryCommand) {
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"--help"}, {"generate", "--help"}, {"world", "--help"},
        {"validate", "--help"}, {"version", "--help"}, {"assets", "build", "--help"},
        {"merge", "--help"}, {"bench", "--help"}, {"profile", "placement", "--help"}}) {
    const CliResult r = run(args);
    EXPECT_EQ(r.code, 0) << ::testing::PrintToString(args);
    EXPECT_NE(r.out.find("Examples:"), std::string::npos) << r.out;
    EXPECT_EQ(r.err, "");
  }
}

}  // namespace
}  // namespace silva::app
