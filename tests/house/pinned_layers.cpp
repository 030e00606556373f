#include "pinned_layers.hpp"

#include <sstream>
#include <string_view>

namespace silva::house {
namespace {

/// One pinned layer: a folder and, space-separated, the folders below it that it may ever include.
struct Pin {
  std::string_view folder;   ///< e.g. "render"
  std::string_view ceiling;  ///< e.g. "core"
};

// Bottom up, whatever the doc says: its table may allow a folder less than its ceiling, never more.
constexpr Pin kPins[] = {
    {"core", ""},
    {"ecs", ""},
    {"components", "core ecs"},
    {"assets", "core"},
    {"world", "core assets"},
    {"render", "core"},
    {"raycast", "core"},
    {"io", "core"},
    {"systems", "core ecs components assets world render raycast io"},
    {"web", ""},
    {"pipeline", "core ecs components assets world render raycast io systems"},
    {"bench", "core ecs components assets world render raycast io systems pipeline"},
    {"app", "core ecs components assets world render raycast io systems web pipeline bench"},
};

}  // namespace

std::vector<FolderRule> pinned_rules() {
  std::vector<FolderRule> rules;
  for (const Pin& pin : kPins) {
    FolderRule rule{std::string(pin.folder), std::string(pin.ceiling), {}};
    std::istringstream words(rule.may_include);
    for (std::string w; words >> w;) rule.allowed.insert(w);
    rules.push_back(std::move(rule));
  }
  return rules;
}

std::string loosened_edges(const std::vector<FolderRule>& rules) {
  const std::vector<FolderRule> pins = pinned_rules();
  std::ostringstream out;
  for (const FolderRule& r : rules) {
    const FolderRule pin = rule_for(pins, r.folder);
    for (const std::string& x : r.allowed) {
      if (pin.allowed.count(x) != 0) continue;
      out << "docs/DESIGN.md: " << r.folder << "/ may include " << x << "/, beyond the pinned layering (at most: "
          << allowed_list(pin) << ")\n";
    }
  }
  return out.str();
}

}  // namespace silva::house
