#include "core/season.hpp"

#include <iterator>

namespace silva {

namespace {
constexpr std::string_view kNames[] = {"summer", "autumn", "winter", "spring", "early_spring"};
}  // namespace

std::string_view season_name(Season s) { return kNames[int(s)]; }

bool parse_season(std::string_view name, Season& out) {
  for (int i = 0; i < int(std::size(kNames)); ++i)
    if (name == kNames[i]) {
      out = Season(i);
      return true;
    }
  return false;
}

}  // namespace silva
