#include "link_lines.hpp"

#include <map>
#include <sstream>

#include "cmake_calls.hpp"
#include "source_tree.hpp"

namespace silva::house {
namespace {

namespace fs = std::filesystem;

/// One of our CMake files and its calls.
struct CMakeFile {
  std::string name;              ///< relative to the root
  std::string folder;            ///< its source folder; empty for the root's
  std::vector<CMakeCall> calls;  ///< in order
};

/// root/CMakeLists.txt and every root/<source folder>/CMakeLists.txt there is.
std::vector<CMakeFile> cmake_files(const fs::path& root) {
  std::vector<CMakeFile> files{{"CMakeLists.txt", "", cmake_calls(read_text(root / "CMakeLists.txt"))}};
  for (const std::string_view folder : kSourceFolders) {
    const std::string name = std::string(folder) + "/CMakeLists.txt";
    if (fs::exists(root / name)) files.push_back({name, std::string(folder), cmake_calls(read_text(root / name))});
  }
  return files;
}

/// The folder of each library that silva_library or a folder's add_library defines.
std::map<std::string, std::string> defined_folders(const std::vector<CMakeFile>& files) {
  std::map<std::string, std::string> folders;
  for (const CMakeFile& f : files) {
    for (const CMakeCall& c : f.calls) {
      if (c.command == "silva_library" && c.args.size() >= 2) folders[c.args[0]] = c.args[1].substr(0, c.args[1].find('/'));
      if (c.command == "add_library" && !f.folder.empty() && !c.args.empty()) folders[c.args[0]] = f.folder;
    }
  }
  return folders;
}

/// The source folder of `library`, or empty.
std::string folder_of(const std::map<std::string, std::string>& defined, const std::string& library) {
  const auto it = defined.find(library);
  if (it != defined.end()) return is_source_folder(it->second) ? it->second : std::string();
  const std::string prefix = "silva_";
  const std::string x = library.rfind(prefix, 0) == 0 ? library.substr(prefix.size()) : std::string();
  return is_source_folder(x) ? x : std::string();
}

/// The libraries `call` links to `call.args[0]`, or none when it is no link call.
std::vector<std::string> linked(const CMakeCall& call) {
  if (call.command == "silva_library" && call.args.size() >= 2) return std::vector<std::string>(call.args.begin() + 2, call.args.end());
  if (call.command != "target_link_libraries" || call.args.empty()) return {};
  std::vector<std::string> deps;
  for (auto it = call.args.begin() + 1; it != call.args.end(); ++it) {
    if (*it != "PUBLIC" && *it != "PRIVATE" && *it != "INTERFACE") deps.push_back(*it);
  }
  return deps;
}

/// The allowed folders of `rule`, comma-separated, or "none of ours".
std::string may_include(const FolderRule& rule) {
  std::string out;
  for (const std::string& f : rule.allowed) out += (out.empty() ? "" : ", ") + f;
  return out.empty() ? "none of ours" : out;
}

}  // namespace

std::vector<LinkLine> link_lines(const fs::path& root) {
  const std::vector<CMakeFile> files = cmake_files(root);
  const std::map<std::string, std::string> defined = defined_folders(files);
  std::vector<LinkLine> lines;
  for (const CMakeFile& f : files) {
    for (const CMakeCall& c : f.calls) {
      for (const std::string& dep : linked(c)) {
        LinkLine line{f.name, c.args[0], folder_of(defined, c.args[0]), dep, folder_of(defined, dep)};
        if (!line.library_folder.empty() && !line.dep_folder.empty()) lines.push_back(std::move(line));
      }
    }
  }
  return lines;
}

std::string link_violations(const fs::path& root, const std::vector<FolderRule>& rules) {
  std::ostringstream out;
  for (const LinkLine& l : link_lines(root)) {
    const FolderRule rule = rule_for(rules, l.library_folder);
    if (l.dep_folder == l.library_folder || rule.allowed.count(l.dep_folder) != 0) continue;
    out << l.file << ": " << l.library << " links " << l.dep << " (" << l.library_folder
        << "/ may include: " << may_include(rule) << ")\n";
  }
  return out.str();
}

}  // namespace silva::house
