#pragma once
/// @file The product's default forest view for the peers bench: the default world (default config,
/// seed 1234567890, built-in assets) seen from the middle autopilot pose at 1920x1080, LODs on.
#include <memory>
#include <vector>

#include "assets/library.hpp"
#include "core/camera.hpp"
#include "render/scene.hpp"
#include "systems/prepare_scene.hpp"

namespace silva::bench {

/// One capture view of the default world, plus the same view frozen to what Silva draws so the
/// peers get exactly the triangles Silva rasterises.
struct DefaultView {
  std::unique_ptr<assets::AssetLibrary> library;  ///< Owner of the asset meshes the scenes point into.
  systems::FrameScene frame;                        ///< The view's chunks as the capture pipeline builds them.
  Camera camera;                                  ///< The middle autopilot pose, 1920x1080.
  /// The instances Silva draws from `camera` with LODs on, in the same order, each with a
  /// single-LOD mesh: the LOD Silva selected (the peers' scene; draw it with render.lod = false).
  render::Scene drawn;
  std::vector<uint32_t> drawn_from;  ///< Index in frame.scene.instances of each drawn instance.
  /// Builds the world's chunks for the view, the scene, and Silva's LOD selection.
  DefaultView();
  /// Triangles of the drawn instances at their LODs (what every renderer of the view is given).
  size_t triangle_count() const;
};

/// The shared default view, built on first use.
const DefaultView& default_view();

}  // namespace silva::bench
