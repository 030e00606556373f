#include "pipeline/console/version.hpp"

namespace silva::pipeline {

const char* silva_version() { return SILVA_VERSION; }

const char* git_revision() { return SILVA_GIT_REV; }

std::string version_line() { return std::string("silva ") + silva_version() + " (git " + git_revision() + ")"; }

}  // namespace silva::pipeline
