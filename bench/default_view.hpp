#pragma once
/// @file The product's default forest view for the peers bench: the default world (default config,
/// seed 1234567890, built-in assets) seen from the middle autopilot pose at 1920x1080, with LODs on
/// and at full detail (render.lod = false).
#include <memory>
#include <vector>

#include "assets/library.hpp"
#include "core/camera.hpp"
#include "render/scene.hpp"
#include "systems/prepare_scene.hpp"

namespace silva::bench {

/// The instances Silva draws of a view, in its order, each with a single-LOD mesh: the LOD Silva
/// selected (a scene the peers get exactly the triangles of; draw it with render.lod = false).
struct FrozenView {
  render::Scene scene;        ///< The drawn instances at their LODs.
  std::vector<uint32_t> from;  ///< Index in the full scene's instances of each drawn instance.
  /// Triangles of the drawn instances at their LODs (what every renderer of the view is given).
  size_t triangle_count() const;
};

/// One capture view of the default world, plus the same view frozen to what Silva draws, with LODs
/// and at full detail, so the peers get exactly the triangles Silva rasterises.
struct DefaultView {
  std::unique_ptr<assets::AssetLibrary> library;  ///< Owner of the asset meshes the scenes point into.
  systems::FrameScene frame;                        ///< The view's chunks as the capture pipeline builds them.
  Camera camera;                                  ///< The middle autopilot pose, 1920x1080.
  FrozenView drawn;        ///< What Silva draws with LODs on (the default).
  FrozenView full_detail;  ///< What Silva draws with render.lod = false: every drawn instance at LOD 0.
  /// Builds the world's chunks for the view, the scene, and Silva's selections with and without LODs.
  DefaultView();
};

/// The shared default view, built on first use.
const DefaultView& default_view();

}  // namespace silva::bench
