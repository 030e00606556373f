#pragma once
/// @file Mesa llvmpipe visibility peer: OpenGL 4.5 core on the CPU through an EGL surfaceless context.
#include <memory>

#include "bench/peer_frame.hpp"

namespace silva::bench {

/// Draws a view with Mesa's llvmpipe into an FBO (32-bit float reverse depth + RG32UI
/// instance/triangle ids; alpha test in the fragment shader with the scene's mask, nearest,
/// repeat). Meshes are uploaded once as static VBO/IBOs; each instance part is one draw call.
/// One peer per process at a time: it sets GALLIUM_DRIVER and LP_NUM_THREADS in the environment.
class LlvmpipePeer {
 public:
  /// Creates the context with `lp_threads` llvmpipe rasteriser threads (0 = all work on the
  /// calling thread) and uploads the scene (the setup, timed into setup_ms()).
  LlvmpipePeer(const PeerView& view, int lp_threads);
  /// Deletes the GL objects and terminates the EGL display.
  ~LlvmpipePeer();
  LlvmpipePeer(const LlvmpipePeer&) = delete;
  LlvmpipePeer& operator=(const LlvmpipePeer&) = delete;
  /// Draws one frame and waits for it (glFinish); with `readback`, also reads depth and ids back.
  void render(bool readback);
  /// The last frame read back, converted to camera z and scene indices.
  PeerFrame frame() const;
  /// Milliseconds context creation, shader compilation and upload took.
  double setup_ms() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace silva::bench
