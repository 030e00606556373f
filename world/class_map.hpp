#pragma once
/// @file A top-down orthographic class map of a built world (a splat, not the rasteriser):
/// ground; every object as a disc of its asset's top-view radius in the colour of the class
/// seen from above (canopy for trees), taller objects over lower ones; then, as plan overlays,
/// the trail (terrain triangles whose centroid lies on its overlay) and each solid's collision footprint in its own class (trunk, stump...).
#include <cstdint>
#include <vector>

#include "assets/library.hpp"
#include "core/ontology.hpp"
#include "world/world_summary.hpp"

namespace silva::world {

/// An 8-bit RGB image, row-major; the top row is the north edge (largest y).
struct ClassMap {
  int width = 0;             ///< Pixels along +x.
  int height = 0;            ///< Pixels along -y.
  double x0 = 0, y1 = 0;     ///< World x of the left edge and y of the top edge (metres).
  double metres_per_pixel = 1;  ///< Ground sample distance.
  std::vector<uint8_t> rgb;  ///< width * height * 3 bytes.
};

/// Renders the class map of `world` (chunks of edge chunk_size) over the bounding box of its
/// chunks; colours come from `ontology`, object radii and top classes from `library` (coarsest LOD).
ClassMap render_class_map(const BuiltWorld& world, double chunk_size, const assets::AssetLibrary& library,
                          const Ontology& ontology, double metres_per_pixel);

}  // namespace silva::world
