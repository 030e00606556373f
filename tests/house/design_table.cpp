#include "design_table.hpp"

#include <cctype>
#include <regex>
#include <sstream>

#include "source_tree.hpp"

namespace silva::house {
namespace {

std::string trimmed(std::string_view s) {
  const std::size_t b = s.find_first_not_of(" \t\r");
  if (b == std::string_view::npos) return {};
  const std::size_t e = s.find_last_not_of(" \t\r");
  return std::string(s.substr(b, e - b + 1));
}

// The words of a cell: runs of letters, digits and '_'.
std::vector<std::string> words(std::string_view cell) {
  std::vector<std::string> out;
  std::string word;
  for (const char c : cell) {
    if (std::isalnum(static_cast<unsigned char>(c)) || c == '_') {
      word += c;
    } else if (!word.empty()) {
      out.push_back(word);
      word.clear();
    }
  }
  if (!word.empty()) out.push_back(word);
  return out;
}

// The folder named by a first cell "`folder/`", or empty.
std::string folder_of_cell(std::string_view cell) {
  static const std::regex kFolder(R"(^`([a-z_]+)/`$)");
  std::smatch m;
  const std::string text = trimmed(cell);
  if (!std::regex_match(text, m, kFolder)) return {};
  return m[1].str();
}

}  // namespace

std::vector<FolderRule> parse_design_table(std::string_view markdown) {
  std::vector<FolderRule> rules;
  for (const std::string& raw : split_lines(markdown)) {
    const std::string line = trimmed(raw);
    if (line.size() < 2 || line.front() != '|' || line.back() != '|') continue;
    const std::size_t first_end = line.find('|', 1);
    const std::size_t last_start = line.rfind('|', line.size() - 2);
    if (first_end == std::string::npos || last_start <= first_end) continue;  // fewer than 3 cells
    const std::string folder = folder_of_cell(std::string_view(line).substr(1, first_end - 1));
    if (!is_source_folder(folder)) continue;
    FolderRule rule{folder, trimmed(std::string_view(line).substr(last_start + 1, line.size() - last_start - 2)), {}};
    for (const std::string& w : words(rule.may_include)) {
      if (is_source_folder(w)) rule.allowed.insert(w);
    }
    if (rule.may_include.find("everything above") != std::string::npos) {
      for (const FolderRule& above : rules) rule.allowed.insert(above.folder);
    }
    rule.allowed.erase(rule.folder);
    rules.push_back(std::move(rule));
  }
  return rules;
}

std::string allowed_list(const FolderRule& rule) {
  std::string out = rule.folder;
  for (const std::string& f : rule.allowed) out += ", " + f;
  return out;
}

std::string format_rules(const std::vector<FolderRule>& rules) {
  std::ostringstream out;
  out << "docs/DESIGN.md's folder table, as read (folder: may include -> allowed source folders):\n";
  for (const FolderRule& r : rules) {
    out << "  " << r.folder << "/: \"" << r.may_include << "\" -> " << allowed_list(r) << "\n";
  }
  return out.str();
}

std::vector<FolderRule> design_rules(const std::filesystem::path& root) {
  return parse_design_table(read_text(root / "docs/DESIGN.md"));
}

FolderRule rule_for(const std::vector<FolderRule>& rules, std::string_view folder) {
  for (const FolderRule& r : rules) {
    if (r.folder == folder) return r;
  }
  return FolderRule{std::string(folder), {}, {}};
}

}  // namespace silva::house
