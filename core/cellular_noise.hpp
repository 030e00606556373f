#pragma once
/// @file Stateless 3D cellular (Worley) noise: one hashed feature point per unit lattice cell, the
/// distances to the nearest two and the gradient of their gap, for cracks between cells.
#include <cstdint>

namespace silva {

/// The nearest two feature points of cellular noise at a point (in the noise's own coordinates).
struct CellularSample {
  float f1 = 0.0f;               ///< Distance to the nearest feature point.
  float f2 = 0.0f;               ///< Distance to the second-nearest feature point.
  float gap_dx = 0.0f;           ///< Gradient of f2 - f1 (zero where it is 0 on the border itself).
  float gap_dy = 0.0f;           ///< (as gap_dx, y)
  float gap_dz = 0.0f;           ///< (as gap_dx, z)
  uint32_t nearest_cell = 0;     ///< Hash of the nearest feature point's cell: an id per cell.
};

/// Cellular noise at (x, y, z). Cell (i, j, k)'s feature point lies at (i, j, k) + (a, b, c) / 1024,
/// a, b, c the bits 0-9, 10-19 and 20-29 of lattice_hash(i, j, k, salt); the nearest two are
/// searched among the 27 cells around the point's own.
CellularSample cellular3(float x, float y, float z, uint32_t salt);

}  // namespace silva
