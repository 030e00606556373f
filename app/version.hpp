#pragma once
/// @file Silva's version text (SILVA_VERSION and SILVA_GIT_REV come from CMake).
#include <string>

namespace silva::app {

/// "silva 0.1.0 (git abc1234)".
std::string version_line();

}  // namespace silva::app
