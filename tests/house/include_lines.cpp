#include "include_lines.hpp"

#include <regex>
#include <sstream>

#include "source_tree.hpp"

namespace silva::house {

namespace fs = std::filesystem;

std::string included_source_folder(std::string_view file, std::string_view line) {
  static const std::regex kInclude(R"(^\s*#\s*include\s*([<"])([^>"]*)[>"])");
  std::match_results<std::string_view::const_iterator> m;
  if (!std::regex_search(line.begin(), line.end(), m, kInclude)) return {};
  const std::string path = m[2].str();
  const std::string first = path.substr(0, path.find('/'));
  const bool from_root = m[1] == "<" || is_source_folder(first) || first == "tests";
  const fs::path resolved = (from_root ? fs::path(path) : fs::path(file).parent_path() / path).lexically_normal();
  if (!resolved.has_parent_path()) return {};  // a file at the root, or nothing
  const std::string top = resolved.begin()->string();
  return is_source_folder(top) ? top : std::string();
}

std::vector<Include> source_includes(const fs::path& root, std::string_view folder) {
  std::vector<Include> includes;
  for (const fs::path& path : source_files(root, folder)) {
    const std::string file = path.lexically_relative(root).generic_string();
    const std::vector<std::string> lines = split_lines(read_text(path));
    for (std::size_t i = 0; i < lines.size(); ++i) {
      std::string reached = included_source_folder(file, lines[i]);
      if (!reached.empty()) includes.push_back({file, i + 1, lines[i], std::move(reached)});
    }
  }
  return includes;
}

std::string include_violations(const fs::path& root, const std::vector<FolderRule>& rules) {
  std::ostringstream out;
  for (const std::string_view folder : kSourceFolders) {
    const FolderRule rule = rule_for(rules, folder);
    for (const Include& inc : source_includes(root, folder)) {
      if (inc.folder == folder || rule.allowed.count(inc.folder) != 0) continue;
      out << inc.file << ":" << inc.line << " includes " << inc.folder << "/ (allowed: " << allowed_list(rule) << ")\n";
    }
  }
  return out.str();
}

}  // namespace silva::house
