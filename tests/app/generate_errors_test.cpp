// Bad input to `silva generate`: the exit code of CONTRACT.md, one stderr line naming the
// file/key/value, and the earlier run in the output folder left byte for byte as it was.
#include <gtest/gtest.h>

#include <unistd.h>

#include <fstream>

#include "generate_errors_fixture.hpp"

namespace silva::test {
namespace {

namespace fs = std::filesystem;

TEST_F(GenerateErrors, MissingPoseFile) {
  const std::string missing = (dir_ / "nope.json").string();
  expect_refused(custom(missing), 2, {missing});
}

TEST_F(GenerateErrors, PoseFileNotJson) {
  const std::string f = write("broken.json", "{\"poses\": [ {\"position\": [1, 2");
  expect_refused(custom(f), 2, {f});
}

TEST_F(GenerateErrors, PoseFileWrongField) {
  const std::string f =
      write("wrong.json", R"({"poses": [{"position": [1, 2, 3], "yaw": 5, "pitch_deg": 0, "roll_deg": 0}]})");
  expect_refused(custom(f), 2, {f, "pose 0", "yaw_deg"});
  const std::string g =
      write("string.json", R"({"poses": [{"position": "here", "yaw_deg": 5, "pitch_deg": 0, "roll_deg": 0}]})");
  expect_refused(custom(g), 2, {g, "position", "here"});
  const std::string h = write("empty.json", R"({"poses": []})");
  expect_refused(custom(h), 2, {h, "no poses"});
}

TEST_F(GenerateErrors, PoseFileNaNAndNonOrthonormalMatrix) {
  const std::string csv = write("nan.csv", "x,y,z,yaw_deg,pitch_deg,roll_deg\n1,2,3,0,0,0\n4,5,6,nan,0,0\n");
  expect_refused(custom(csv), 2, {csv, "line 3", "yaw_deg", "nan"});
  const std::string inf = write("inf.csv", "x,y,z,yaw_deg,pitch_deg,roll_deg\n1,inf,3,0,0,0\n");
  expect_refused(custom(inf), 2, {inf, "'y'", "inf"});
  const std::string json =
      write("nan.json", R"({"poses": [{"position": [1, 2, 3], "yaw_deg": NaN, "pitch_deg": 0, "roll_deg": 0}]})");
  expect_refused(custom(json), 2, {json});
  const std::string skew = write(
      "skew.json", R"({"poses": [{"camera_to_world": [[1, 0.1, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]}]})");
  expect_refused(custom(skew), 2, {skew, "orthonormal", "1e-5"});
}

TEST_F(GenerateErrors, BadSequenceName) {
  expect_refused(args({"--set", R"(captures.sequences=["autopilot","bogus"])"}), 2, {"captures.sequences", "bogus"});
  expect_refused(args({"--set", R"(captures.sequences=["custom"])"}), 2, {"captures.poses_file"});
}

TEST_F(GenerateErrors, RigCameraInsideAnObjectAndUnknownRig) {
  // A 2 m baseline puts the right camera of autopilot frame 34 of this world inside a shrub; --overwrite keeps the
  // earlier run, as the plan fails before anything is written.
  expect_refused(args({"--overwrite", "--set", "rig.preset=stereo", "--set", "rig.baseline_m=2", "--set",
                       "captures.autopilot_points=20", "--set", "captures.random_count=20"}),
                 2, {"rig.baseline_m = 2", "the right camera of autopilot frame 34", "inside a shrub"});
  expect_refused(args({"--set", "rig.preset=tripod"}), 2, {"rig.preset", "tripod", "ground_robot", "drone"});
}

TEST_F(GenerateErrors, UnwritableOutputFolder) {
  const std::string file = write("a_file", "not a folder");
  const std::vector<std::string> a = {"generate", "--seed", "1", "--out", file + "/sub"};
  const ProcessResult r = run_silva(a, dir_);
  EXPECT_EQ(r.code, 3) << r.err;
  ASSERT_EQ(lines_of(r.err).size(), 1u) << r.err;
  EXPECT_NE(r.err.find(file), std::string::npos) << r.err;
  if (::geteuid() == 0) return;  // root writes into read-only folders
  const fs::path locked = dir_ / "locked";
  fs::create_directories(locked);
  fs::permissions(locked, fs::perms::owner_read | fs::perms::owner_exec);
  const ProcessResult l = run_silva({"generate", "--seed", "1", "--out", (locked / "o").string()}, dir_);
  fs::permissions(locked, fs::perms::owner_all);
  EXPECT_EQ(l.code, 3) << l.err;
  EXPECT_NE(l.err.find(locked.string()), std::string::npos) << l.err;
}

TEST_F(GenerateErrors, ExistingRunFolder) {
  const std::string run_dir = (out_ / "0000002024").string();
  // Same config, no flag: suggests --resume / --overwrite.
  expect_refused(args({}), 2, {run_dir, "--resume", "--overwrite"});
  // A different config, with and without --resume.
  expect_refused(args({"--set", "captures.random_count=3"}), 2, {run_dir, "different config", "--overwrite"});
  expect_refused(args({"--set", "captures.random_count=3", "--resume"}), 2, {run_dir, "different config"});
  // --overwrite and --resume together.
  expect_refused(args({"--resume", "--overwrite"}), 2, {"--overwrite", "--resume"});
}

TEST_F(GenerateErrors, ResumeOfACompleteRunRendersNothing) {
  const ProcessResult r = run_silva(args({"--resume", "--json"}), dir_);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("\"frames_written\":0"), std::string::npos) << r.out;
  EXPECT_EQ(file_differences(folder_files(out_), before_plain_), "");
}

TEST_F(GenerateErrors, OverwriteReplacesTheRun) {
  const ProcessResult r = run_silva(args({"--set", R"(captures.sequences=["random"])", "--overwrite"}), dir_);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_FALSE(fs::exists(out_ / "0000002024" / "autopilot"));
  EXPECT_TRUE(fs::exists(out_ / "0000002024" / "random" / "camera" / "000001.json"));
}

}  // namespace
}  // namespace silva::test
