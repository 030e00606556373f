#pragma once
/// @file Small shared math aliases (Eigen) used across Silva.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>

namespace silva {

using Vec2f = Eigen::Vector2f;  ///< 2D float vector.
using Vec3f = Eigen::Vector3f;  ///< 3D float vector (world: metres, Z up).
using Vec4f = Eigen::Vector4f;  ///< 4D float vector.
using Vec3d = Eigen::Vector3d;  ///< 3D double vector.
using Mat3f = Eigen::Matrix3f;  ///< 3x3 float matrix.
using Mat4f = Eigen::Matrix4f;  ///< 4x4 float matrix.
using Mat4d = Eigen::Matrix4d;  ///< 4x4 double matrix.
using Mat3d = Eigen::Matrix3d;  ///< 3x3 double matrix.
using Affine3f = Eigen::Matrix<float, 3, 4>;  ///< Rigid/affine transform as a 3x4 matrix [R|t].

/// Integer chunk coordinates: chunk (i, j) covers [i*s,(i+1)*s) x [j*s,(j+1)*s).
struct ChunkCoord {
  int32_t i = 0;  ///< Index along world X.
  int32_t j = 0;  ///< Index along world Y.
  friend bool operator==(ChunkCoord a, ChunkCoord b) { return a.i == b.i && a.j == b.j; }
  friend bool operator<(ChunkCoord a, ChunkCoord b) { return a.i != b.i ? a.i < b.i : a.j < b.j; }
  /// Packs the coordinates into one 64-bit key for hashing and RNG keys.
  uint64_t key() const { return (uint64_t(uint32_t(i)) << 32) | uint32_t(j); }
};

}  // namespace silva
