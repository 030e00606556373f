#include "rule_graph.hpp"

#include <algorithm>
#include <map>
#include <set>

namespace silva::house {
namespace {

/// A depth-first walk of the allowed edges that keeps the path it is on.
struct CycleSearch {
  std::map<std::string, std::set<std::string>> edges;  ///< folder -> allowed folders
  std::set<std::string> done;                          ///< folders whose every path was walked
  std::vector<std::string> path;                       ///< the folders being walked, outermost first

  /// The cycle through `folder` or below it, or empty.
  std::string walk(const std::string& folder) {
    path.push_back(folder);
    for (const std::string& next : edges[folder]) {
      const auto on_path = std::find(path.begin(), path.end(), next);
      if (on_path != path.end()) {
        std::string cycle;
        for (auto it = on_path; it != path.end(); ++it) cycle += *it + " -> ";
        return cycle + next;
      }
      if (done.count(next) != 0) continue;
      std::string cycle = walk(next);
      if (!cycle.empty()) return cycle;
    }
    path.pop_back();
    done.insert(folder);
    return {};
  }
};

}  // namespace

std::string find_cycle(const std::vector<FolderRule>& rules) {
  CycleSearch search;
  for (const FolderRule& r : rules) search.edges[r.folder] = r.allowed;
  for (const FolderRule& r : rules) {
    if (search.done.count(r.folder) != 0) continue;
    std::string cycle = search.walk(r.folder);
    if (!cycle.empty()) return cycle;
  }
  return {};
}

}  // namespace silva::house
