#include "io/run_folder.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "core/error.hpp"
#include "io_test_util.hpp"

namespace silva::io {
namespace {

namespace fs = std::filesystem;

TEST(RunFolder, SeedFolderNameHasTenDigits) {
  EXPECT_EQ(seed_folder_name(42), "0000000042");
  EXPECT_EQ(seed_folder_name(9999999999), "9999999999");
}

TEST(RunFolder, FreshResumeAndOverwrite) {
  const fs::path out = test::scratch_dir("run_folder_modes");
  const fs::path run = prepare_run_folder(out, 7, "abc", FolderMode::Fresh);
  EXPECT_EQ(run, out / "0000000007");
  ASSERT_TRUE(read_run_marker(run).has_value());
  EXPECT_EQ(read_run_marker(run)->config_hash, "abc");
  EXPECT_EQ(find_resumable_seed(out), 7);
  std::ofstream(run / "frame.png") << "x";
  std::ofstream(temp_path_for(run / "half.png")) << "y";
  // Same config: Fresh refuses, Resume continues and drops the temp file, Shard continues.
  EXPECT_THROW(prepare_run_folder(out, 7, "abc", FolderMode::Fresh), InputError);
  EXPECT_NO_THROW(prepare_run_folder(out, 7, "abc", FolderMode::Shard));
  EXPECT_TRUE(fs::exists(temp_path_for(run / "half.png")));
  EXPECT_NO_THROW(prepare_run_folder(out, 7, "abc", FolderMode::Resume));
  EXPECT_FALSE(fs::exists(temp_path_for(run / "half.png")));
  EXPECT_TRUE(fs::exists(run / "frame.png"));
  // Another config: refused unless Overwrite, which empties the folder.
  for (FolderMode m : {FolderMode::Fresh, FolderMode::Resume, FolderMode::Shard})
    EXPECT_THROW(prepare_run_folder(out, 7, "other", m), InputError);
  EXPECT_TRUE(fs::exists(run / "frame.png"));
  EXPECT_NO_THROW(prepare_run_folder(out, 7, "other", FolderMode::Overwrite));
  EXPECT_FALSE(fs::exists(run / "frame.png"));
  EXPECT_EQ(read_run_marker(run)->config_hash, "other");
}

TEST(RunFolder, AFolderWithOnlyTheMarkersTempFileHoldsNoRun) {
  // A run killed while writing its marker leaves just the marker's temp file.
  const fs::path out = test::scratch_dir("run_folder_killed_early");
  const fs::path run = out / "0000000003";
  fs::create_directories(run);
  for (FolderMode m : {FolderMode::Fresh, FolderMode::Resume}) {
    std::ofstream(temp_path_for(run / ".silva-run.json")) << "{\"se";
    EXPECT_NO_THROW(prepare_run_folder(out, 3, "h", m));
    EXPECT_TRUE(list_temp_files(run).empty());
    fs::remove(run / ".silva-run.json");
  }
  // Files that are not a run are never taken over.
  std::ofstream(run / "notes.txt") << "mine";
  EXPECT_THROW(prepare_run_folder(out, 3, "h", FolderMode::Resume), InputError);
  EXPECT_TRUE(fs::exists(run / "notes.txt"));
}

TEST(RunFolder, CorruptMarkerIsBadInput) {
  const fs::path run = test::scratch_dir("run_folder_corrupt") / "0000000001";
  fs::create_directories(run);
  std::ofstream(run / ".silva-run.json") << "{not json";
  EXPECT_THROW(read_run_marker(run), InputError);
  EXPECT_THROW(prepare_run_folder(run.parent_path(), 1, "h", FolderMode::Resume, ""), InputError);
  // --overwrite, which the corrupt marker's message advises, empties the folder whatever its marker holds.
  std::ofstream(run / "old.txt") << "x";
  EXPECT_EQ(prepare_run_folder(run.parent_path(), 1, "h", FolderMode::Overwrite, ""), run);
  EXPECT_FALSE(fs::exists(run / "old.txt"));
  ASSERT_TRUE(read_run_marker(run));
  EXPECT_EQ(read_run_marker(run)->config_hash, "h");
}

}  // namespace
}  // namespace silva::io
