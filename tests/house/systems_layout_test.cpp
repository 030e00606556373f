// systems/ holds ECS systems only: one registration per file, each declaring its access.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

#include "code_text.hpp"
#include "source_tree.hpp"

namespace silva::house {
namespace {

std::size_t count_of(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

TEST(Layering, SystemsRegisterOneSystemEach) {
  std::ostringstream out;
  for (const auto& file : source_files(source_root(), "systems")) {
    if (file.extension() == ".hpp") {
      std::filesystem::path cpp = file;
      if (!std::filesystem::exists(cpp.replace_extension(".cpp"))) out << shown(file) << ": no .cpp beside it\n";
      continue;
    }
    const std::string code = code_only(read_text(file));
    const std::size_t systems = count_of(code, ".system(\"");
    if (systems != 1) out << shown(file) << ": registers " << systems << " systems (.system(\"...\")), not 1\n";
    if (count_of(code, ".reads") + count_of(code, ".writes") == 0) out << shown(file) << ": declares no .reads/.writes\n";
  }
  EXPECT_TRUE(out.str().empty()) << out.str();
}

}  // namespace
}  // namespace silva::house
