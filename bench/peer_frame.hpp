#pragma once
/// @file What every visibility peer of peers_bench produces, and how two such frames are compared.
#include <cstdint>
#include <vector>

#include "core/camera.hpp"
#include "render/raster_conventions.hpp"
#include "render/scene.hpp"
#include "render/visibility.hpp"

namespace silva::bench {

/// What a visibility peer draws: a scene whose meshes it takes at lods[0] and a camera (both
/// outlive the peer).
struct PeerView {
  const render::Scene* scene = nullptr;  ///< Instances and meshes (lods[0] only).
  const Camera* camera = nullptr;        ///< Pose and intrinsics.
};

/// Per-pixel visibility of one view, row-major, row 0 at the top (image v = 0).
struct PeerFrame {
  int width = 0;                   ///< Pixels across.
  int height = 0;                  ///< Pixels down.
  std::vector<float> depth;        ///< Camera-space z of the hit in metres, 0 = no hit.
  std::vector<uint32_t> instance;  ///< Scene instance index, render::kNoInstance = no hit.
  std::vector<uint32_t> triangle;  ///< Triangle index within the instance's mesh.
  /// Sizes the planes for w x h and clears them to "no hit".
  void resize(int w, int h);
};

/// Converts Silva's visibility buffer (reverse depth 1/z) to a PeerFrame.
PeerFrame from_visibility(const render::VisibilityBuffer& v);

/// How far a peer's frame agrees with a reference frame.
struct Agreement {
  double instance = 0;  ///< Fraction of pixels with the same instance (no-hit included).
  double triangle = 0;  ///< Fraction of pixels with the same instance and triangle.
  double depth = 0;     ///< Of the pixels both hit, the fraction with |z - z_ref| <= tolerance * z_ref.
};

/// Compares `peer` with `reference` (same size); depth tolerance relative to the reference z.
Agreement compare(const PeerFrame& peer, const PeerFrame& reference, double depth_tolerance);

}  // namespace silva::bench
