#include "source_tree.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>

namespace silva::house {

namespace fs = std::filesystem;

bool is_source_folder(std::string_view name) {
  return std::find(std::begin(kSourceFolders), std::end(kSourceFolders), name) != std::end(kSourceFolders);
}

fs::path source_root() { return fs::path(SILVA_SOURCE_DIR); }

std::vector<fs::path> source_files(const fs::path& root, std::string_view folder) {
  std::vector<fs::path> files;
  const fs::path dir = root / folder;
  if (!fs::is_directory(dir)) return files;
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(dir)) {
    const std::string ext = e.path().extension().string();
    if (e.is_regular_file() && (ext == ".cpp" || ext == ".hpp")) files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<std::string> split_lines(std::string_view text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    lines.emplace_back(text.substr(start, end - start));
    start = end + 1;
  }
  return lines;
}

std::string shown(const fs::path& path) { return path.lexically_relative(source_root()).generic_string(); }

}  // namespace silva::house
