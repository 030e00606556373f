#pragma once
/// @file printf into a std::string, for the text file formats (COLMAP, TUM, EuRoC, Kalibr).
#include <cstdio>
#include <string>

namespace silva::io {

/// The text std::snprintf makes of `pattern` and `args`, of any length.
template <class... Args>
std::string printf_string(const char* pattern, Args... args) {
  const int n = std::snprintf(nullptr, 0, pattern, args...);
  std::string out(size_t(n > 0 ? n : 0) + 1, '\0');
  std::snprintf(out.data(), out.size(), pattern, args...);
  out.pop_back();
  return out;
}

}  // namespace silva::io
