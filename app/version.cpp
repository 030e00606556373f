#include "app/version.hpp"

namespace silva::app {

std::string version_line() { return std::string("silva ") + SILVA_VERSION + " (git " + SILVA_GIT_REV + ")"; }

}  // namespace silva::app
