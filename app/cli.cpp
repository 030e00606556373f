#include "app/cli.hpp"

#include <cstdio>

namespace silva::app {

int run_cli(int, char**) {
  std::fprintf(stderr, "silva: not yet implemented\n");
  return 1;
}

}  // namespace silva::app
