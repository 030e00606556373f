// Hostile and careless input to the CLI: deep nesting, huge numbers, far-away poses, planted
// links, files that are folders, a second writer. Each answers with one line and the documented
// exit code and leaves the earlier run byte for byte as it was.
#include <gtest/gtest.h>

#include <signal.h>
#include <stdlib.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <thread>

#include "generate_errors_fixture.hpp"
#include "tests/common/scoped_env.hpp"
#include "textured_library.hpp"

namespace silva::test {
namespace {

/// True once process `pid` has a handler for SIGTERM (bit 15 of SigCgt in /proc/<pid>/status).
bool catches_sigterm(pid_t pid) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("SigCgt:", 0) == 0) return (std::stoull(line.substr(7), nullptr, 16) >> (SIGTERM - 1)) & 1;
  return false;
}

/// JSON text of a pose whose position is nested `depth` arrays deep.
std::string deep_pose(int depth) {
  return R"({"poses": [{"position": )" + std::string(size_t(depth), '[') + "1" + std::string(size_t(depth), ']') +
         R"(, "yaw_deg": 0, "pitch_deg": 0, "roll_deg": 0}]})";
}

/// A copy of the project's configs/ folder under `root` (a SILVA_DATA folder).
fs::path copy_data_folder(const fs::path& root) {
  fs::create_directories(root);
  fs::copy(fs::path(SILVA_SOURCE_DIR) / "configs", root / "configs", fs::copy_options::recursive);
  return root;
}

TEST_F(GenerateErrors, DeeplyNestedPoseFileIsOneShortLine) {
  for (int depth : {30000, 60000}) {
    const std::string f = write("deep" + std::to_string(depth) + ".json", deep_pose(depth));
    expect_refused(custom(f), 2, {f, "nested deeper than 64"});
    const ProcessResult r = run_silva(custom(f), dir_);
    EXPECT_LT(r.err.size(), 400u) << r.err.substr(0, 400);
  }
}

TEST_F(GenerateErrors, DeeplyNestedOntologyIsRefused) {
  const fs::path data = copy_data_folder(dir_ / "data");
  std::ofstream(data / "configs" / "ontology.json") << std::string(60000, '[') << std::string(60000, ']');
  const ScopedEnv env("SILVA_DATA", data.string());
  expect_refused(args({"--overwrite"}), 2, {"ontology.json", "nested deeper than 64"});
}

TEST_F(GenerateErrors, NumberBeyondADoubleIsBadInput) {
  const std::string f = write("huge.json", R"({"poses": [{"position": [1e400, 0, 2], "yaw_deg": 0, "pitch_deg": 0,
                                                "roll_deg": 0}]})");
  expect_refused(custom(f), 2, {f, "not valid JSON"});
  const fs::path data = copy_data_folder(dir_ / "data");
  std::string ontology = read_file(data / "configs" / "ontology.json");
  ontology.replace(ontology.find("\"id\":0"), 6, "\"id\":1e400");
  std::ofstream(data / "configs" / "ontology.json") << ontology;
  const ScopedEnv env("SILVA_DATA", data.string());
  expect_refused(args({"--overwrite"}), 2, {"ontology.json"});
}

TEST_F(GenerateErrors, DataFilesThatAreFoldersAreBadInput) {
  const fs::path data = copy_data_folder(dir_ / "data");
  fs::remove(data / "configs" / "lighting.toml");
  fs::create_directories(data / "configs" / "lighting.toml");
  {
    const ScopedEnv env("SILVA_DATA", data.string());
    expect_refused(args({"--overwrite"}), 2, {"lighting.toml", "not a regular file"});
  }
  const fs::path library = dir_ / "library";
  fs::create_directories(library / "library.json");
  const ScopedEnv env("SILVA_ASSETS", library.string());
  expect_refused(args({"--overwrite"}), 2, {"library.json", "not a regular file"});
}

TEST_F(GenerateErrors, UndecodableTextureIsSilvasOneLineOnly) {
  // An OBJ asset whose material names a texture file that is not there: OpenCV's imread logs a
  // "[ WARN ... ] imread_(...): can't open/read file" line of its own unless Silva silences it.
  const fs::path library = dir_ / "library";
  textured_obj_library(library, "photo.png");
  const ScopedEnv env("SILVA_ASSETS", library.string());
  expect_refused(args({"--overwrite"}), 2, {"a.obj", "texture 'photo.png' cannot be decoded"});
}

/// A PNG of 4 x 4 grey pixels whose header chunk fails its CRC.
std::string corrupt_png() {
  std::string png = "\x89PNG\r\n\x1a\n";
  png += std::string("\0\0\0\x0dIHDR\0\0\0\x04\0\0\0\x04\x08\0\0\0\0", 21);
  png += std::string("\x8c\x7a\x6b\x5a", 4);  // not IHDR's CRC either: the first chunk already fails
  png += std::string("\0\0\0\x02IDAT\x78\x9c\0\0\0\0", 14);
  return png;
}

TEST_F(GenerateErrors, CorruptTextureIsSilvasOneLineOnly) {
  // libpng prints "libpng error: ..." on stderr for a corrupt PNG unless Silva checks it first.
  const fs::path library = dir_ / "library";
  textured_obj_library(library, "photo.png");
  std::ofstream(library / "photo.png", std::ios::binary) << corrupt_png();
  const ScopedEnv env("SILVA_ASSETS", library.string());
  expect_refused(args({"--overwrite"}), 2, {"a.obj", "texture 'photo.png'", "fails its CRC"});
}

TEST_F(GenerateErrors, CorruptDatasetImageIsOneLineOnly) {
  const fs::path png = out_ / "0000002024" / "random" / "semantic" / "000001.png";
  std::string bytes = read_file(png);
  bytes[bytes.size() - 20] = char(bytes[bytes.size() - 20] ^ 0x55);  // inside the last IDAT
  std::ofstream(png, std::ios::binary | std::ios::trunc) << bytes;
  const ProcessResult r = run_silva({"card", (out_ / "0000002024").string()}, dir_);
  EXPECT_EQ(r.code, 2) << r.err;
  ASSERT_EQ(lines_of(r.err).size(), 1u) << r.err;
  EXPECT_NE(r.err.find("semantic/000001.png: PNG chunk IDAT fails its CRC"), std::string::npos) << r.err;
  std::ofstream(png, std::ios::binary | std::ios::trunc) << before_.at("0000002024/random/semantic/000001.png");
}

TEST_F(GenerateErrors, FarAwayPosesAreRefusedBeforeAnythingIsWritten) {
  const std::string f = write("far.json", R"({"poses": [{"position": [0, 0, 2], "yaw_deg": 0, "pitch_deg": 0, "roll_deg": 0},
    {"position": [1e12, 0, 2], "yaw_deg": 0, "pitch_deg": 0, "roll_deg": 0}]})");
  expect_refused(custom(f), 2, {f, "pose 1", "out of range", "100000"});
  const std::string g = write("far.csv", "x,y,z,yaw_deg,pitch_deg,roll_deg\n1e300,-1e300,,0,0,0\n");
  expect_refused(custom(g), 2, {g, "line 2", "out of range"});
  const fs::path fresh = dir_ / "fresh";
  const ProcessResult r = run_silva({"generate", "--seed", "5", "--out", fresh.string(), "--set",
                                     R"(captures.sequences=["custom"])", "--set", "captures.poses_file=" + g},
                                    dir_);
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_FALSE(fs::exists(fresh / "0000000005")) << "nothing may be written for bad input";
}

TEST_F(GenerateErrors, MorePosesThanSixDigitsAreRefused) {
  std::string csv = "x,y,z,yaw_deg,pitch_deg,roll_deg\n";
  csv.reserve(12'000'000);
  for (int k = 0; k <= 1'000'000; ++k) csv += "0,0,,0,0,0\n";
  const std::string f = write("many.csv", csv);
  expect_refused(custom(f), 2, {f, "more than 1000000 poses"});
}

TEST_F(GenerateErrors, CsvWithByteOrderMarkIsRead) {
  const std::string f = write("bom.csv", "\xEF\xBB\xBFx,y,z,yaw_deg,pitch_deg,roll_deg\n1,2,,0,0,0\n");
  const fs::path out = dir_ / "bom";
  std::vector<std::string> a = custom(f);
  a[4] = out.string();  // --out
  const ProcessResult r = run_silva(a, dir_);
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(fs::exists(out / "0000002024" / "custom" / "camera" / "000000.json"));
}

TEST_F(GenerateErrors, UnknownTablesAndSmuggledLinesAreRefused) {
  for (const std::string table : {"camrea", "foo.bar.baz", "camera.extra"}) {
    const std::string f = write("unknown.toml", "[" + table + "]\n");
    expect_refused(args({"--config", f}), 2, {f, table});
  }
  expect_refused(args({"--set", "camera.fov_deg=90\n[evil]\nx=1"}), 2, {"--set", "line break"});
  const std::string missing = (dir_ / "missing.json").string();
  const ProcessResult v = run_silva({"validate", "--set", R"(captures.sequences=["custom"])", "--set",
                                     "captures.poses_file=" + missing},
                                    dir_);
  EXPECT_EQ(v.code, 2) << v.err;
  EXPECT_NE(v.err.find(missing), std::string::npos) << v.err;
}

TEST_F(GenerateErrors, ClearLinesForCommandsAndRanges) {
  const ProcessResult unknown = run_silva({"frobnicate"}, dir_);
  EXPECT_EQ(unknown.code, 2);
  EXPECT_NE(unknown.err.find("unknown command 'frobnicate'"), std::string::npos) << unknown.err;
  const ProcessResult radius = run_silva({"world", "--seed", "1", "--center", "0,0", "--radius", "-5"}, dir_);
  EXPECT_EQ(radius.code, 2);
  ASSERT_EQ(lines_of(radius.err).size(), 1u) << radius.err;
  EXPECT_LT(radius.err.size(), 160u) << radius.err;
  const ProcessResult huge = run_silva({"world", "--seed", "1", "--center", "0,0", "--radius", "1e9"}, dir_);
  EXPECT_EQ(huge.code, 2) << huge.err;
}

TEST_F(GenerateErrors, CostGuardRefusesWhatTheMachineCannotDo) {
  // A 10 km far plane: ~1e5 chunks in one view, 2.5e7 placement points per frame.
  expect_refused(args({"--overwrite", "--set", "camera.far=10000"}), 2, {"placement points", "chunks", "--force"});
  // A chunk of 1024 m at 1 cm vertex spacing: 1e10 vertices per chunk.
  expect_refused(args({"--overwrite", "--set", "terrain.chunk_size=1024", "--set", "terrain.vertex_spacing=0.01"}), 2,
                 {"GB of memory", "--force"});
  const ProcessResult world = run_silva({"world", "--seed", "1", "--center", "0,0", "--radius", "90000"}, dir_);
  EXPECT_EQ(world.code, 2) << world.err;
  EXPECT_NE(world.err.find("--force"), std::string::npos) << world.err;
}

TEST_F(GenerateErrors, OverwriteThroughASymlinkedSeedFolderIsRefused) {
  const fs::path outside = dir_ / "outside";
  fs::create_directories(outside);
  std::ofstream(outside / "precious.txt") << "keep";
  const fs::path linked = dir_ / "linked";
  fs::create_directories(linked);
  fs::create_directory_symlink(outside, linked / "0000002024");
  std::vector<std::string> a = args({"--overwrite"});
  a[4] = linked.string();  // --out
  const ProcessResult r = run_silva(a, dir_);
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("symbolic link"), std::string::npos) << r.err;
  EXPECT_EQ(read_file(outside / "precious.txt"), "keep");
}

TEST_F(GenerateErrors, ShardDoesNotWriteThroughAPlantedTempLink) {
  const fs::path outside = dir_ / "victim.txt";
  std::ofstream(outside) << "keep";
  const fs::path rgb_dir = out_ / "0000002024" / "random" / "semantic";
  fs::remove(rgb_dir / "000001.png");
  fs::remove(out_ / "0000002024" / "random" / "camera" / "000001.json");
  fs::create_symlink(outside, rgb_dir / "000001.png.tmp-silva");
  const ProcessResult r = run_silva(args({"--shard", "0/1"}), dir_);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(read_file(outside), "keep");
  EXPECT_FALSE(fs::is_symlink(rgb_dir / "000001.png"));
  EXPECT_EQ(read_file(rgb_dir / "000001.png"), before_.at("0000002024/random/semantic/000001.png"));
}

TEST_F(GenerateErrors, MergeRefusesAMissingFrameFile) {
  const fs::path shard_out = dir_ / "shards";
  std::vector<std::string> a = args({"--shard", "0/1"});
  a[4] = shard_out.string();  // --out
  ASSERT_EQ(run_silva(a, dir_).code, 0);
  const fs::path run = shard_out / "0000002024";
  fs::remove(run / "random" / "depth" / "000001.png");
  const ProcessResult r = run_silva({"merge", run.string()}, dir_);
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("depth/000001.png"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(run / "manifest.json"));
}

TEST_F(GenerateErrors, EditedPoseFileIsAnotherRun) {
  const std::string f = write("poses.csv", "x,y,z,yaw_deg,pitch_deg,roll_deg\n1,2,,0,0,0\n3,4,,0,0,0\n");
  std::vector<std::string> a = custom(f);
  a[4] = (dir_ / "custom").string();  // --out
  ASSERT_EQ(run_silva(a, dir_).code, 0);
  const fs::path run = dir_ / "custom" / "0000002024";
  fs::remove(run / "custom" / "camera" / "000001.json");
  write("poses.csv", "x,y,z,yaw_deg,pitch_deg,roll_deg\n1,2,,0,0,0\n5,6,,90,0,0\n");
  a.push_back("--resume");
  const ProcessResult r = run_silva(a, dir_);
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("different config or input files"), std::string::npos) << r.err;
  EXPECT_NE(read_file(run / "manifest.json").find("poses_file"), std::string::npos);
}

TEST_F(GenerateErrors, ResumeWithoutSetReadsTheConfigFromTheMarker) {
  // The interrupt hint: `silva generate --resume --out DIR --seed N`, without the original --set.
  const fs::path run = out_ / "0000002024";
  fs::remove(run / "random" / "camera" / "000001.json");
  const ProcessResult r = run_silva({"generate", "--resume", "--out", out_.string(), "--seed", "2024"}, dir_);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(file_differences(folder_files(out_), before_plain_), "");
}

TEST_F(GenerateErrors, ResumeRewritesAFrameWhoseOutputFileWasDeleted) {
  // merge's hint for a missing file is "rerun its shard": the rerun must write the frame again, not skip it
  // because its camera file is still there.
  const fs::path run = out_ / "0000002024";
  fs::remove(run / "random" / "semantic" / "000001.png");
  const ProcessResult r = run_silva({"generate", "--resume", "--out", out_.string(), "--seed", "2024"}, dir_);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(file_differences(folder_files(out_), before_plain_), "");
}

TEST_F(GenerateErrors, ResumeOfAMissingRunSaysThereIsNothingToResume) {
  const fs::path empty = dir_ / "never-run";
  const ProcessResult r = run_silva({"generate", "--resume", "--out", empty.string(), "--seed", "77"}, dir_);
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("nothing to resume"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(empty)) << "--resume started a fresh run";
}

TEST_F(GenerateErrors, SecondWriterIsRefusedNamingThePid) {
  const fs::path slow = dir_ / "slow";
  std::vector<std::string> a = args({"--set", "captures.random_count=400", "--set", R"(captures.sequences=["random"])"});
  a[4] = slow.string();  // --out
  fs::create_directories(dir_ / "first");
  const ChildProcess first = start_silva(a, dir_ / "first");
  const fs::path marker = slow / "0000002024" / ".silva-run.json";
  for (int k = 0; k < 600 && !fs::exists(marker); ++k) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  ASSERT_TRUE(fs::exists(marker));
  a.push_back("--overwrite");
  const ProcessResult second = run_silva(a, dir_);
  ::kill(first.pid, SIGINT);
  const ProcessResult stopped = wait_silva(first);
  EXPECT_EQ(second.code, 2) << second.err;
  EXPECT_NE(second.err.find("PID " + std::to_string(first.pid)), std::string::npos) << second.err;
  EXPECT_EQ(stopped.code, 130) << stopped.err;
}

TEST_F(GenerateErrors, SecondWriterWhileMergeHoldsTheLockIsRefused) {
  std::vector<std::string> shard = args({"--shard", "0/1"});
  shard[4] = (dir_ / "shards").string();  // --out
  ASSERT_EQ(run_silva(shard, dir_).code, 0);
  const fs::path run = dir_ / "shards" / "0000002024";
  fs::create_directories(dir_ / "merge");
  const ChildProcess merge = start_silva({"merge", run.string()}, dir_ / "merge", /*traced=*/true);
  ASSERT_TRUE(stop_after_lock(merge));  // merge holds the lock and waits here
  std::vector<std::string> overwrite = shard;
  overwrite.erase(overwrite.end() - 2, overwrite.end());
  overwrite.push_back("--overwrite");
  const ProcessResult late_shard = run_silva(shard, dir_);
  const ProcessResult fresh_run = run_silva(overwrite, dir_);
  release_traced(merge);
  const ProcessResult merged = wait_silva(merge);
  for (const ProcessResult* second : {&late_shard, &fresh_run}) {
    EXPECT_EQ(second->code, 2) << second->err;
    EXPECT_EQ(lines_of(second->err).size(), 1u) << second->err;
    EXPECT_NE(second->err.find("in use by another silva process (PID " + std::to_string(merge.pid) + ")"),
              std::string::npos)
        << second->err;
  }
  EXPECT_EQ(merged.code, 0) << merged.err;
  EXPECT_TRUE(fs::is_regular_file(run / "manifest.json"));
}

TEST_F(GenerateErrors, MergeWhileAShardWritesIsRefused) {
  std::vector<std::string> shard = args({"--shard", "0/1"});
  shard[4] = (dir_ / "shards").string();  // --out
  ASSERT_EQ(run_silva(shard, dir_).code, 0);
  const fs::path run = dir_ / "shards" / "0000002024";
  fs::remove(run / "random" / "depth" / "000001.png");
  fs::create_directories(dir_ / "shard");
  const ChildProcess rerun = start_silva(shard, dir_ / "shard", /*traced=*/true);
  ASSERT_TRUE(stop_after_lock(rerun));  // the shard holds its shared lock and waits here
  const ProcessResult merged = run_silva({"merge", run.string()}, dir_);
  release_traced(rerun);
  EXPECT_EQ(wait_silva(rerun).code, 0);
  EXPECT_EQ(merged.code, 2) << merged.err;
  EXPECT_NE(merged.err.find("(PID " + std::to_string(rerun.pid) + ")"), std::string::npos) << merged.err;
  EXPECT_FALSE(fs::exists(run / "manifest.json"));
}

TEST_F(GenerateErrors, SecondResumeIsRefusedNamingThePid) {
  fs::remove(out_ / "0000002024" / "random" / "camera" / "000001.json");
  const std::vector<std::string> resume = args({"--resume"});
  fs::create_directories(dir_ / "first");
  const ChildProcess first = start_silva(resume, dir_ / "first", /*traced=*/true);
  ASSERT_TRUE(stop_after_lock(first));
  const ProcessResult second = run_silva(resume, dir_);
  release_traced(first);
  const ProcessResult finished = wait_silva(first);
  EXPECT_EQ(second.code, 2) << second.err;
  EXPECT_NE(second.err.find("(PID " + std::to_string(first.pid) + ")"), std::string::npos) << second.err;
  EXPECT_EQ(finished.code, 0) << finished.err;
  EXPECT_EQ(file_differences(folder_files(out_), before_plain_), "");
}

TEST_F(GenerateErrors, TerminateWhilePlanningStopsAtOnce) {
  const fs::path planning = dir_ / "planning";
  std::vector<std::string> a = args({"--set", "captures.random_count=1000000", "--set", "world.extent=4096"});
  a[4] = planning.string();  // --out
  fs::create_directories(dir_ / "child");
  const ChildProcess child = start_silva(a, dir_ / "child");
  // Wait until the process catches SIGTERM (its handler is installed first thing), then let it plan.
  for (int k = 0; k < 600 && !catches_sigterm(child.pid); ++k)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  std::this_thread::sleep_for(std::chrono::milliseconds(1000));
  const auto t0 = std::chrono::steady_clock::now();
  ::kill(child.pid, SIGTERM);
  const ProcessResult r = wait_silva(child);
  EXPECT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(3));
  EXPECT_EQ(r.code, 130) << r.err;
  EXPECT_NE(r.err.find("interrupted"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(planning / "0000002024"));
}

}  // namespace
}  // namespace silva::test
