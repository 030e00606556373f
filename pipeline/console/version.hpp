#pragma once
/// @file Silva's version text (the version and git revision come from CMake, into version.cpp only).
#include <string>

namespace silva::pipeline {

/// The release version, e.g. "0.1.0".
const char* silva_version();
/// The short git revision the binary was configured at, or "unknown".
const char* git_revision();
/// "silva 0.1.0 (git abc1234)".
std::string version_line();

}  // namespace silva::pipeline
