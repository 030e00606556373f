#pragma once
/// @file Embree 3 visibility peer: one primary ray per pixel centre through a two-level BVH.
#include <memory>

#include "bench/peer_frame.hpp"

namespace silva::bench {

/// Traces a view with Embree 3 through raycast::RayScene (one BVH per mesh, an intersection filter
/// for alpha-masked parts, a top-level BVH of instances). Build and trace run on TBB in the
/// caller's task_arena.
class EmbreePeer {
 public:
  /// Builds the BVHs (the setup, timed into setup_ms()).
  explicit EmbreePeer(const PeerView& view);
  /// Releases the BVHs and the device.
  ~EmbreePeer();
  EmbreePeer(const EmbreePeer&) = delete;
  EmbreePeer& operator=(const EmbreePeer&) = delete;
  /// Traces one frame of the scene's camera into `out` (resized to the camera's size).
  void render(PeerFrame& out) const;
  /// Milliseconds the BVH builds took.
  double setup_ms() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace silva::bench
