// End to end through the built `silva` binary: every bad-input case gives its exact one-line
// message and exit code, writes nothing and leaves an earlier run untouched; the defaults and
// `validate --print` hold when read back from the process's output.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "pipeline/config/config_loader.hpp"
#include "tests/common/config_equal.hpp"
#include "silva_process.hpp"
#include "app/cli/pipeline_names.hpp"

namespace silva::app {
namespace {

namespace fs = std::filesystem;
using silva::test::ProcessResult;
using silva::test::read_file;

/// Every entry under `root`: relative path -> content (files) or "<dir>", plus its write time.
std::map<std::string, std::string> snapshot(const fs::path& root) {
  std::map<std::string, std::string> entries;
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(root)) {
    const std::string time = std::to_string(e.last_write_time().time_since_epoch().count());
    entries[fs::relative(e.path(), root).string()] =
        (e.is_directory() ? std::string("<dir>") : read_file(e.path())) + " @" + time;
  }
  return entries;
}

class ConfigBinary : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = silva::test::fresh_test_dir();
    work_ = dir_ / "work";
    fs::create_directories(work_ / "out" / "0000001234" / "rgb");
    fs::create_directories(dir_ / "io");
    std::ofstream(work_ / "out" / "0000001234" / ".silva-run.json") << "{\"config_hash\":\"earlier\"}";
    std::ofstream(work_ / "out" / "0000001234" / "rgb" / "000000.png") << "earlier run";
    out_ = (work_ / "out").string();
  }
  void TearDown() override { fs::remove_all(dir_); }

  /// Runs the silva binary with `args`; stdout and stderr are captured outside the work folder.
  ProcessResult run(const std::vector<std::string>& args) const { return silva::test::run_silva(args, dir_ / "io"); }

  /// Writes `text` as work/<name> and returns its path.
  std::string write_config(const std::string& name, const std::string& text) const {
    const fs::path path = work_ / name;
    std::ofstream(path, std::ios::binary) << text;
    return path.string();
  }

  /// `silva generate ARGS --out work/out --seed 1234` exits `code` with exactly `message` on
  /// stderr, nothing on stdout, and the work folder (an earlier run, the configs) byte for byte
  /// and time for time as before.
  void expect_rejected(std::vector<std::string> args, int code, const std::string& message) const {
    const auto before = snapshot(work_);
    args.insert(args.begin(), "generate");
    for (const char* a : {"--out", out_.c_str(), "--seed", "1234"}) args.emplace_back(a);
    const ProcessResult r = run(args);
    EXPECT_EQ(r.code, code) << ::testing::PrintToString(args);
    EXPECT_EQ(r.err, "silva: error: " + message + "\n");
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(snapshot(work_), before) << "bad input must not touch anything on disk";
  }

  fs::path dir_, work_;
  std::string out_;
};

TEST_F(ConfigBinary, UnknownKeyNamesItAndSuggestsTheClosest) {
  const std::string config = write_config("a.toml", "[vegetation]\ndensty = 5\n");
  expect_rejected({"--config", config}, 2,
                  config + ":2:10: unknown key 'vegetation.densty' (did you mean 'vegetation.density'?)");
  expect_rejected({"--set", "terrain.lacunarty=2"}, 2,
                  "--set terrain.lacunarty=2: unknown key 'terrain.lacunarty' (did you mean "
                  "'terrain.lacunarity'?)");
}

TEST_F(ConfigBinary, WrongTypeNamesKeyExpectedAndGot) {
  const std::string config = write_config("a.toml", "[captures]\naerial = 1\n");
  expect_rejected({"--config", config}, 2,
                  config + ":2:10: captures.aerial must be a boolean (true or false), got an integer (1)");
  expect_rejected({"--set", "captures.random_count=many"}, 2,
                  "--set captures.random_count=many: captures.random_count must be an integer, got 'many'");
}

TEST_F(ConfigBinary, OutOfRangeSaysTheAllowedRange) {
  const std::string config = write_config("a.toml", "[vegetation]\ndensity = 0.5\n");
  expect_rejected({"--config", config}, 2,
                  config + ":2:11: vegetation.density = 0.5 is out of range (allowed: 1 to 25)");
  expect_rejected({"--set", "captures.random_count=-1"}, 2,
                  "--set captures.random_count=-1: captures.random_count = -1 is out of range "
                  "(allowed: 0 to 1000000)");
}

TEST_F(ConfigBinary, MissingOrUnreadableConfigFile) {
  const std::string missing = (work_ / "missing.toml").string();
  expect_rejected({"--config", missing}, 2, "config file '" + missing + "' not found");
  const std::string folder = (work_ / "out").string();
  expect_rejected({"--config", folder}, 2,
                  "config file '" + folder + "' is a directory, expected a TOML file");
}

TEST_F(ConfigBinary, CorruptTomlIsOneLineWithPosition) {
  const std::string config = write_config("a.toml", std::string("seed = 1\n\x01\xff\xfe[\0x", 15));
  const auto before = snapshot(work_);
  const ProcessResult r = run({"generate", "--config", config, "--out", out_});
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err.rfind("silva: error: " + config + ":2:1: invalid TOML: ", 0), 0u) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line: " << r.err;
  EXPECT_EQ(snapshot(work_), before);
}

TEST_F(ConfigBinary, BadSetSyntax) {
  expect_rejected({"--set", "vegetation.density"}, 2,
                  "--set vegetation.density: expected key=value, e.g. --set camera.fov_deg=75");
  expect_rejected({"--set", "output.types=[\"rgb\""}, 2,
                  "--set output.types=[\"rgb\": output.types must be an array of strings, got "
                  "'[\"rgb\"' (a TOML array, e.g. [\"rgb\",\"depth\"])");
}

TEST_F(ConfigBinary, UnwritableOutputFolderIsAnIoError) {
  const fs::path file = work_ / "a_file";
  std::ofstream(file) << "x";
  const auto before = snapshot(work_);
  const std::string out = (file / "out").string();
  const ProcessResult r = run({"generate", "--seed", "1234", "--out", out});
  EXPECT_EQ(r.code, 3);
  EXPECT_EQ(r.err, "silva: error: output folder '" + out + "' cannot be created: '" + file.string() +
                       "' is not a folder\n");
  EXPECT_EQ(snapshot(work_), before);
}

TEST_F(ConfigBinary, DefaultsAreTheThesisDefaultsWithAClockSeed) {
  const ProcessResult r = run({"validate", "--print"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err, "silva: no seed given; this run would draw one from the clock\n");
  const LoadedConfig printed = parse_config_text(r.out, "printed");
  EXPECT_TRUE(printed.seed_given) << "the drawn seed is printed";
  EXPECT_GE(printed.config.seed, 0);
  EXPECT_LE(printed.config.seed, 9999999999);
  Config thesis;
  thesis.seed = printed.config.seed;
  EXPECT_EQ(testing::config_differences(printed.config, thesis), "");
  const Config& c = printed.config;
  EXPECT_EQ(c.output.width, 1920);
  EXPECT_EQ(c.output.height, 1080);
  EXPECT_EQ(c.captures.random_count, 100);
  EXPECT_EQ(c.vegetation.density, 5);
  EXPECT_EQ(c.terrain.max_elevation, 1.5);
  EXPECT_FALSE(c.captures.aerial);
  EXPECT_TRUE(c.trail.enabled);
  EXPECT_EQ(c.terrain.lacunarity, 2.0);
  EXPECT_EQ(c.terrain.persistence, 0.5);
  EXPECT_EQ(c.lighting.time_of_day, "day");
}

TEST_F(ConfigBinary, ValidatePrintIsAFixedPoint) {
  const ProcessResult first = run({"validate", "--config", SILVA_SOURCE_DIR "/configs/demo.toml",
                                   "--set", "terrain.persistence=0.45", "--set", "output.dir=\"a b\"",
                                   "--print"});
  ASSERT_EQ(first.code, 0) << first.err;
  const std::string printed = write_config("printed.toml", first.out);
  const ProcessResult second = run({"validate", "--config", printed, "--print"});
  ASSERT_EQ(second.code, 0) << second.err;
  EXPECT_EQ(second.out, first.out);
  const LoadedConfig again = parse_config_text(second.out, "printed");
  EXPECT_EQ(again.config.terrain.persistence, 0.45);
  EXPECT_EQ(again.config.output.dir, "a b");
  EXPECT_EQ(again.config.seed, 1234567890);
}

}  // namespace
}  // namespace silva::app
