#pragma once
/// @file The fixture of the bad-input tests of `silva generate`: a tiny first run in a scratch
/// folder, and a check that a refused command leaves every file of it as it was.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "silva_process.hpp"

namespace silva::test {

namespace fs = std::filesystem;

constexpr int64_t kSeed = 2024;

/// A finished tiny run of seed kSeed under out_, and helpers to refuse commands against it.
class GenerateErrors : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fresh_test_dir();
    out_ = dir_ / "out";
    const ProcessResult first = run_silva(tiny_run_args(out_, kSeed), dir_);
    ASSERT_EQ(first.code, 0) << first.err;
    before_ = folder_files(out_, /*with_run_records=*/true);
    before_plain_ = folder_files(out_);
    ASSERT_TRUE(before_.count("0000002024/manifest.json"));
  }

  /// Writes `text` to a file in the test folder; returns its path.
  std::string write(const std::string& name, const std::string& text) {
    const fs::path path = dir_ / name;
    std::ofstream(path) << text;
    return path.string();
  }

  /// The tiny run's arguments plus `extra`.
  std::vector<std::string> args(std::vector<std::string> extra) const {
    std::vector<std::string> a = tiny_run_args(out_, kSeed);
    a.insert(a.end(), extra.begin(), extra.end());
    return a;
  }

  /// Args running only the custom sequence from `pose_file`.
  std::vector<std::string> custom(const std::string& pose_file) const {
    return args({"--set", R"(captures.sequences=["custom"])", "--set", "captures.poses_file=" + pose_file});
  }

  /// Expects exit `code`, exactly one stderr line holding every string of `named`, nothing on
  /// stdout, and the earlier output untouched.
  void expect_refused(const std::vector<std::string>& a, int code, const std::vector<std::string>& named) {
    const ProcessResult r = run_silva(a, dir_);
    EXPECT_EQ(r.code, code) << r.err;
    const auto lines = lines_of(r.err);
    ASSERT_EQ(lines.size(), 1u) << r.err;
    EXPECT_EQ(lines[0].rfind("silva: error: ", 0), 0u) << lines[0];
    for (const std::string& n : named)
      EXPECT_NE(lines[0].find(n), std::string::npos) << "missing '" << n << "': " << lines[0];
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(file_differences(folder_files(out_, true), before_), "");
  }

  fs::path dir_, out_;
  std::map<std::string, std::string> before_;        ///< Every file of the first run.
  std::map<std::string, std::string> before_plain_;  ///< The same without run.json.
};

}  // namespace silva::test
