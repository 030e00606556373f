#include "core/season.hpp"

namespace silva {

namespace {
constexpr std::string_view kNames[] = {"summer", "autumn", "winter"};
}  // namespace

std::string_view season_name(Season s) { return kNames[int(s)]; }

bool parse_season(std::string_view name, Season& out) {
  for (int i = 0; i < 3; ++i)
    if (name == kNames[i]) {
      out = Season(i);
      return true;
    }
  return false;
}

}  // namespace silva
