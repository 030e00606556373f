#include "core/input_limits.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "core/error.hpp"

namespace silva::limits {
namespace {

TEST(InputLimits, NestingDepthSkipsStringsAndEscapes) {
  EXPECT_EQ(json_nesting_depth("1"), 0);
  EXPECT_EQ(json_nesting_depth(R"({"a": [[1], {"b": [2]}]})"), 4);
  EXPECT_EQ(json_nesting_depth(R"({"a": "[[[[\"[[["})"), 1);
  EXPECT_EQ(json_nesting_depth(std::string(100000, '[')), kMaxJsonDepth + 1);  // stops counting early
}

TEST(InputLimits, DepthCheckNamesTheSource) {
  EXPECT_NO_THROW(check_json_depth(std::string(64, '[') + std::string(64, ']'), "f.json"));
  try {
    check_json_depth(std::string(65, '['), "f.json");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "f.json: JSON nested deeper than 64 levels");
  }
}

TEST(InputLimits, ReadInputFileRefusesFoldersAndMissingFiles) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::path(::testing::TempDir()) / ("silva_limits_" + std::to_string(::getpid()));
  fs::create_directories(dir / "sub");
  std::ofstream(dir / "ok.txt") << "text";
  EXPECT_EQ(read_input_file(dir / "ok.txt", "pose file"), "text");
  EXPECT_THROW(read_input_file(dir / "sub", "pose file"), InputError);
  EXPECT_THROW(read_input_file(dir / "none", "pose file"), InputError);
  fs::remove_all(dir);
}

TEST(InputLimits, QuotedPrefixCutsLongValues) {
  EXPECT_EQ(quoted_prefix("short"), "short");
  EXPECT_EQ(quoted_prefix(std::string(1000, 'x')).size(), kMaxQuotedChars + 3);
}

}  // namespace
}  // namespace silva::limits
