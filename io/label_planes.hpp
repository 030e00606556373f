#pragma once
/// @file The per-pixel planes the label and depth encoders read: a view of a renderer's G-buffer,
/// so io depends on plain spans rather than on the renderer.
#include <cstddef>
#include <cstdint>
#include <span>

#include "core/ontology.hpp"
#include "core/types.hpp"

namespace silva::io {

/// Row-major planes of width*height pixels (not owned). A pixel with depth 0 saw no surface.
struct LabelPlanes {
  int width = 0;                          ///< Pixels across.
  int height = 0;                         ///< Pixels down.
  std::span<const float> depth;           ///< Metric z along the optical axis (metres), 0 = no hit.
  std::span<const Vec3f> normal;          ///< Unit world normal.
  std::span<const Role> role;             ///< Semantic role.
  std::span<const uint32_t> instance_id;  ///< Packed instance id, 0 = none.
  /// Number of pixels.
  size_t size() const { return size_t(width) * size_t(height); }
};

}  // namespace silva::io
