/// @file CMake text read as its command calls (name and arguments), enough to find link lines.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace silva::house {

/// One command call, e.g. `target_link_libraries(silva_web PRIVATE PkgConfig::HTTPLIB)`.
struct CMakeCall {
  std::string command;            ///< as written ("target_link_libraries")
  std::vector<std::string> args;  ///< split at whitespace, quotes removed; may span several lines
};

/// The command calls of CMake `text` in order, comments ("#" to the end of a line) left out.
std::vector<CMakeCall> cmake_calls(std::string_view text);

}  // namespace silva::house
