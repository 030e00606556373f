// Small files and short functions across our sources (tables of data aside).
#include <gtest/gtest.h>

#include <sstream>

#include "function_length.hpp"
#include "source_tree.hpp"

namespace silva::house {
namespace {

constexpr std::size_t kMaxFileLines = 400;
constexpr int kMaxFunctionLines = 80;

TEST(SourceSize, NoFileOver400Lines) {
  std::ostringstream out;
  for (const std::string_view folder : kSourceFolders) {
    for (const auto& file : source_files(source_root(), folder)) {
      const std::size_t n = split_lines(read_text(file)).size();
      if (n > kMaxFileLines) out << shown(file) << ": " << n << " lines\n";
    }
  }
  EXPECT_TRUE(out.str().empty()) << "files over " << kMaxFileLines << " lines:\n" << out.str();
}

TEST(SourceSize, NoFunctionOver80Lines) {
  std::ostringstream out;
  for (const std::string_view folder : kSourceFolders) {
    for (const auto& file : source_files(source_root(), folder)) {
      for (const LongFunction& f : find_long_functions(read_text(file), kMaxFunctionLines)) {
        out << shown(file) << ":" << f.line << ": " << f.lines << " lines: " << f.header << "\n";
      }
    }
  }
  EXPECT_TRUE(out.str().empty()) << "functions over " << kMaxFunctionLines << " lines (tables aside):\n" << out.str();
}

}  // namespace
}  // namespace silva::house
