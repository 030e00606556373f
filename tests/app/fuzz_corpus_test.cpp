// The fuzz corpus (tests/fuzz/corpus/<target>/) replayed through the fuzz entry points with the
// normal compiler, so every build's tests cover it: each input is accepted or refused as bad
// input (InputError/IoError), never another exception or a crash.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "fuzz_entries.hpp"

namespace silva::fuzz {
namespace {

namespace fs = std::filesystem;

TEST(FuzzCorpus, EveryInputIsAcceptedOrRefusedAsBadInput) {
  const fs::path corpus = fs::path(SILVA_SOURCE_DIR) / "tests" / "fuzz" / "corpus";
  for (const FuzzTarget& target : fuzz_targets()) {
    const fs::path dir = corpus / target.name;
    ASSERT_TRUE(fs::is_directory(dir)) << dir;
    int inputs = 0;
    for (const auto& entry : fs::directory_iterator(dir)) {
      std::ifstream in(entry.path(), std::ios::binary);
      std::ostringstream bytes;
      bytes << in.rdbuf();
      SCOPED_TRACE(entry.path().string());
      EXPECT_NO_THROW(run_fuzz_input(target, bytes.str()));
      ++inputs;
    }
    EXPECT_GE(inputs, 1) << target.name << " has no seed input";
  }
}

TEST(FuzzCorpus, SeedsOfTheShippedFilesAreAccepted) {
  // The shipped data files must pass their own readers (so the fuzzer starts from valid input).
  const fs::path corpus = fs::path(SILVA_SOURCE_DIR) / "tests" / "fuzz" / "corpus";
  const std::pair<const char*, const char*> valid[] = {
      {"config", "demo.toml"},        {"pose_json", "example.json"}, {"pose_csv", "example.csv"},
      {"ontology", "ontology.json"},  {"lighting", "lighting.toml"}, {"obj", "tetra.obj"},
      {"gltf", "triangle.gltf"},      {"glb", "triangle.glb"},       {"marker", "marker.json"},
      {"set", "float"},               {"camera_json", "autopilot_000000.json"}, {"png", "semantic_96x64.png"},
      {"manifest", "valid.json"},     {"label_png", "semantic_16x12.png"},      {"label_png", "instance_16x12.png"},
      {"imu_csv", "imu.csv"},         {"imu_yaml", "imu.yaml"},      {"trajectory_file", "groundtruth.txt"},
      {"camera_json", "stereo_right_000000.json"}};
  for (const auto& [name, file] : valid) {
    for (const FuzzTarget& target : fuzz_targets()) {
      if (std::string(target.name) != name) continue;
      std::ifstream in(corpus / name / file, std::ios::binary);
      std::ostringstream bytes;
      bytes << in.rdbuf();
      EXPECT_TRUE(run_fuzz_input(target, bytes.str())) << name << "/" << file;
    }
  }
}

}  // namespace
}  // namespace silva::fuzz
