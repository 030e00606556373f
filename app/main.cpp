#include <malloc.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>

#include "app/cli/cli.hpp"
#include "app/cli/simd_limit.hpp"

namespace {

/// Keeps freed frame-sized buffers in the heap for the next frame. A capture allocates and frees
/// buffers of tens of MB every frame (G-buffer planes, encoders, shading); glibc maps each one afresh
/// and unmaps it on free until its own threshold has crept up over the first frames, so those frames
/// pay their page faults again and again (an 8-set 1080p run is about 5 % faster with this; the
/// steady per-set time is the same: bench/results/amd-epyc-malloc-thresholds.md). A user's own
/// GLIBC_TUNABLES for malloc win.
void keep_frame_buffers_in_heap() {
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  if (tunables && std::strstr(tunables, "glibc.malloc.")) return;
  mallopt(M_MMAP_THRESHOLD, 256 << 20);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
}

}  // namespace

/// Entry point: all work happens in run_cli so tests can call it in-process.
int main(int argc, char** argv) {
  keep_frame_buffers_in_heap();
  if (const char* limit = std::getenv("SILVA_SIMD_LIMIT"); limit && *limit) {
    try {
      silva::app::apply_simd_limit(limit);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "silva: error: %s\n", e.what());
      return 2;
    }
  }
  return silva::app::run_cli(argc, argv);
}
