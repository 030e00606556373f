#pragma once
/// @file Small meshes with known answers for the ray-cast tests: a square, a box, an alpha card.
#include <memory>

#include "core/mesh.hpp"

namespace silva::raycast::test {

/// A square of side `side` centred on the origin in the z = 0 plane, facing +z, one part of `role`.
inline Mesh square(float side, Role role = Role::Ground) {
  Mesh m;
  const float h = side / 2;
  m.positions = {{-h, -h, 0}, {h, -h, 0}, {h, h, 0}, {-h, h, 0}};
  m.normals.assign(4, Vec3f::UnitZ());
  m.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  m.indices = {0, 1, 2, 0, 2, 3};
  MeshPart p;
  p.index_count = 6;
  p.role = role;
  m.parts.push_back(p);
  return m;
}

/// An axis-aligned box of half size `h` centred on the origin, faces outwards, one part of `role`.
inline Mesh box(float h, Role role = Role::Obstacle) {
  Mesh m;
  for (int k = 0; k < 8; ++k) m.positions.push_back(Vec3f(k & 1 ? h : -h, k & 2 ? h : -h, k & 4 ? h : -h));
  m.uvs.assign(8, Vec2f::Zero());
  m.indices = {0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4,
               2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5};
  MeshPart p;
  p.index_count = uint32_t(m.indices.size());
  p.role = role;
  m.parts.push_back(p);
  m.compute_normals();
  return m;
}

/// A vertical card of side `side` in the x = 0 plane (u along +y, v along +z), whose mask is
/// opaque for u < 0.5 and transparent for u >= 0.5 (2 x 1 texels).
inline Mesh alpha_card(float side, Role role = Role::TreeCanopy) {
  Mesh m;
  const float h = side / 2;
  m.positions = {{0, -h, -h}, {0, h, -h}, {0, h, h}, {0, -h, h}};
  m.normals.assign(4, Vec3f::UnitX());
  m.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  m.indices = {0, 1, 2, 0, 2, 3};
  MeshPart p;
  p.index_count = 6;
  p.role = role;
  p.double_sided = true;
  auto mask = std::make_shared<AlphaMask>();
  mask->width = 2;
  mask->height = 1;
  mask->alpha = {255, 0};
  p.mask = mask;
  m.parts.push_back(p);
  return m;
}

/// alpha_card's card with a mask of `texels` x 1 texels, opaque at even u texels (stripes one texel wide).
inline Mesh striped_card(float side, int texels) {
  Mesh m = alpha_card(side);
  auto mask = std::make_shared<AlphaMask>();
  mask->width = texels;
  mask->height = 1;
  for (int k = 0; k < texels; ++k) mask->alpha.push_back(k % 2 ? 0 : 255);
  m.parts[0].mask = mask;
  return m;
}

/// The transform [s*I | t].
inline Affine3f placed(const Vec3f& t, float s = 1.0f) {
  Affine3f a = Affine3f::Zero();
  a.block<3, 3>(0, 0) = s * Mat3f::Identity();
  a.col(3) = t;
  return a;
}

}  // namespace silva::raycast::test
