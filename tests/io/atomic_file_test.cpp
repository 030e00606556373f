#include "io/atomic_file.hpp"

#include <gtest/gtest.h>

#include <sys/resource.h>

#include <csignal>
#include <fstream>
#include <string>

#include "core/error.hpp"
#include "io_test_util.hpp"

namespace silva::io {
namespace {

TEST(AtomicFile, WritesAndReplacesWithoutLeavingTempFiles) {
  const auto dir = test::scratch_dir("atomic_write");
  write_file_atomic(dir / "a.txt", std::string_view("first"));
  write_file_atomic(dir / "a.txt", std::string_view("second, longer"));
  const auto bytes = test::file_bytes(dir / "a.txt");
  EXPECT_EQ(std::string(bytes.begin(), bytes.end()), "second, longer");
  EXPECT_TRUE(list_temp_files(dir).empty());
  EXPECT_EQ(temp_path_for(dir / "a.txt"), dir / "a.txt.tmp-silva");
}

TEST(AtomicFile, UnwritableFolderThrowsIoErrorNamingPath) {
  const auto dir = test::scratch_dir("atomic_unwritable");
  write_file_atomic(dir / "file", std::string_view("x"));
  const auto target = dir / "file" / "sub.png";  // parent is a file: ENOTDIR even for root
  try {
    write_file_atomic(target, std::string_view("data"));
    FAIL();
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find(target.string()), std::string::npos) << e.what();
  }
  EXPECT_THROW(write_file_atomic(dir / "missing" / "x.png", std::string_view("d")), IoError);
  EXPECT_TRUE(list_temp_files(dir).empty());
}

TEST(AtomicFile, FailedRenameRemovesTempAndKeepsTarget) {
  const auto dir = test::scratch_dir("atomic_rename");
  std::filesystem::create_directories(dir / "busy" / "inner");  // a non-empty folder cannot be replaced
  EXPECT_THROW(write_file_atomic(dir / "busy", std::string_view("data")), IoError);
  EXPECT_TRUE(std::filesystem::is_directory(dir / "busy" / "inner"));
  EXPECT_TRUE(list_temp_files(dir).empty());
}

TEST(AtomicFile, WriteFailureThrowsIoErrorAndLeavesNothing) {
  // A file-size limit of 2 bytes makes the write fail (EFBIG) as a full disk would (ENOSPC).
  const auto dir = test::scratch_dir("atomic_full");
  rlimit old{};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &old), 0);
  const auto old_handler = std::signal(SIGXFSZ, SIG_IGN);
  rlimit tiny = old;
  tiny.rlim_cur = 2;
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &tiny), 0);
  bool threw = false;
  try {
    write_file_atomic(dir / "f.bin", std::string_view("data"));
  } catch (const IoError& e) {
    threw = true;
    EXPECT_NE(std::string(e.what()).find((dir / "f.bin").string()), std::string::npos) << e.what();
  }
  ::setrlimit(RLIMIT_FSIZE, &old);
  std::signal(SIGXFSZ, old_handler);
  EXPECT_TRUE(threw);
  EXPECT_FALSE(std::filesystem::exists(dir / "f.bin"));
  EXPECT_TRUE(list_temp_files(dir).empty());
}

TEST(AtomicFile, NeverWritesThroughAPlantedTempLink) {
  const auto dir = test::scratch_dir("atomic_link");
  std::ofstream(dir / "victim.txt") << "keep";
  std::filesystem::create_symlink(dir / "victim.txt", temp_path_for(dir / "f.bin"));
  write_file_atomic(dir / "f.bin", std::string_view("data"));
  EXPECT_FALSE(std::filesystem::is_symlink(dir / "f.bin"));
  std::ifstream victim(dir / "victim.txt");
  std::string text;
  victim >> text;
  EXPECT_EQ(text, "keep");
  std::ifstream written(dir / "f.bin");
  written >> text;
  EXPECT_EQ(text, "data");
}

TEST(AtomicFile, ListsAndRemovesLeftoverTempsRecursively) {
  const auto dir = test::scratch_dir("atomic_leftovers");
  std::filesystem::create_directories(dir / "rgb");
  write_file_atomic(dir / "rgb" / "000001.png.tmp-silva", std::string_view("half"));
  write_file_atomic(dir / "depth.png.tmp-silva", std::string_view("half"));
  write_file_atomic(dir / "rgb" / "000000.png", std::string_view("whole"));
  const auto found = list_temp_files(dir);
  ASSERT_EQ(found.size(), 2u);
  EXPECT_EQ(found[0], dir / "depth.png.tmp-silva");
  EXPECT_EQ(remove_temp_files(dir), 2u);
  EXPECT_TRUE(list_temp_files(dir).empty());
  EXPECT_TRUE(std::filesystem::exists(dir / "rgb" / "000000.png"));
}

}  // namespace
}  // namespace silva::io
