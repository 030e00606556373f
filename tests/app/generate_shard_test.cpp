// `silva generate --shard i/N` into one folder + `silva merge` equals one unsharded run.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "io/atomic_file.hpp"
#include "silva_process.hpp"

namespace silva::test {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> shard_args(const fs::path& out, const std::string& shard) {
  std::vector<std::string> args = tiny_run_args(out, 777, kAllTypes);
  args.insert(args.end(), {"--shard", shard});
  return args;
}

TEST(GenerateShard, TwoShardsMergedEqualOneRun) {
  const fs::path dir = fresh_test_dir();
  const fs::path run_dir = dir / "sharded" / "0000000777";
  const ProcessResult first = run_silva(shard_args(dir / "sharded", "0/2"), dir);
  ASSERT_EQ(first.code, 0) << first.err;
  EXPECT_TRUE(fs::exists(run_dir / "run.shard-0-of-2.json"));
  EXPECT_FALSE(fs::exists(run_dir / "manifest.json"));

  // Merging before every shard is done names the missing shard and writes nothing.
  const ProcessResult early = run_silva({"merge", run_dir.string()}, dir);
  EXPECT_EQ(early.code, 2);
  EXPECT_NE(early.err.find("shard 1 of 2"), std::string::npos) << early.err;
  EXPECT_FALSE(fs::exists(run_dir / "manifest.json"));

  const ProcessResult second = run_silva(shard_args(dir / "sharded", "1/2"), dir);
  ASSERT_EQ(second.code, 0) << second.err;
  const ProcessResult merged = run_silva({"merge", run_dir.string(), "--json"}, dir);
  ASSERT_EQ(merged.code, 0) << merged.err;
  const auto summary = nlohmann::json::parse(merged.out);
  EXPECT_EQ(summary.at("shards"), 2);
  EXPECT_EQ(summary.at("frames"), 5);

  const ProcessResult whole = run_silva(tiny_run_args(dir / "whole", 777, kAllTypes), dir);
  ASSERT_EQ(whole.code, 0) << whole.err;
  EXPECT_TRUE(io::list_temp_files(run_dir).empty());
  EXPECT_EQ(file_differences(folder_files(run_dir), folder_files(dir / "whole" / "0000000777")), "");
}

TEST(GenerateShard, AFolderLinkInsideTheRunFolderIsRefusedNotFollowed) {
  const fs::path dir = fresh_test_dir();
  const fs::path run_dir = dir / "sharded" / "0000000777";
  ASSERT_EQ(run_silva(shard_args(dir / "sharded", "0/2"), dir).code, 0);
  // Planted link: the next shard's depth frames would land in `elsewhere`.
  const fs::path elsewhere = dir / "elsewhere";
  fs::create_directories(elsewhere);
  for (const auto& sequence : fs::directory_iterator(run_dir)) {
    if (!fs::exists(sequence.path() / "depth")) continue;
    fs::rename(sequence.path() / "depth", dir / ("depth-" + sequence.path().filename().string()));
    fs::create_directory_symlink(elsewhere, sequence.path() / "depth");
  }
  const ProcessResult second = run_silva(shard_args(dir / "sharded", "1/2"), dir);
  EXPECT_EQ(second.code, 2) << second.err;
  EXPECT_NE(second.err.find("is a symbolic link"), std::string::npos) << second.err;
  EXPECT_EQ(lines_of(second.err).back().rfind("silva: error: ", 0), 0u) << "one error line, last: " << second.err;
  EXPECT_TRUE(fs::is_empty(elsewhere)) << "frames were written through the link";
}

TEST(GenerateShard, ShardNeedsAnExplicitSeedAndAValidIndex) {
  const fs::path dir = fresh_test_dir();
  std::vector<std::string> no_seed = shard_args(dir / "out", "0/2");
  no_seed.erase(no_seed.begin() + 1, no_seed.begin() + 3);
  const ProcessResult a = run_silva(no_seed, dir);
  EXPECT_EQ(a.code, 2);
  EXPECT_NE(a.err.find("explicit seed"), std::string::npos) << a.err;
  for (const char* bad : {"2/2", "1", "-1/2", "a/b"}) {
    const ProcessResult r = run_silva(shard_args(dir / "out", bad), dir);
    EXPECT_EQ(r.code, 2) << bad;
    EXPECT_NE(r.err.find(std::string("--shard ") + bad), std::string::npos) << r.err;
  }
  EXPECT_FALSE(fs::exists(dir / "out"));
}

}  // namespace
}  // namespace silva::test
