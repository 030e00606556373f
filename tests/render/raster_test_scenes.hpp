#pragma once
/// @file Scene builders shared by the rasteriser tests: quads, grids, trees, rocks, a terrain patch.
#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include "core/camera.hpp"
#include "core/mesh.hpp"
#include "render/scene.hpp"

namespace silva::render::test {

/// A scene that owns its meshes (render::Scene only points at them).
struct OwnedScene {
  std::vector<std::unique_ptr<Mesh>> meshes;  ///< Owned meshes, one LOD each unless added otherwise.
  Scene scene;                                ///< The drawable scene.
  /// Adds a single-LOD mesh and returns its index.
  uint32_t add_mesh(Mesh m) {
    meshes.push_back(std::make_unique<Mesh>(std::move(m)));
    scene.meshes.emplace_back().lods = {meshes.back().get()};
    return uint32_t(scene.meshes.size() - 1);
  }
  /// Adds an instance of mesh `mesh` with a transform, id and variation.
  void add_instance(uint32_t mesh, const Affine3f& xf = Affine3f::Identity(), uint32_t id = 0, uint32_t variation = 0) {
    Instance inst;
    inst.object_to_world = xf;
    inst.mesh = mesh;
    inst.instance_id = id;
    inst.variation = variation;
    scene.instances.push_back(inst);
  }
};

/// Transform: uniform scale, then rotation about world Z, then translation.
inline Affine3f place(const Vec3f& t, float yaw_rad = 0.0f, float scale = 1.0f) {
  Affine3f m;
  m.leftCols<3>() = Eigen::AngleAxisf(yaw_rad, Vec3f::UnitZ()).toRotationMatrix() * scale;
  m.col(3) = t;
  return m;
}

/// Wraps the whole index buffer in one part.
inline void one_part(Mesh& m, Role role, Material material = Material::Ground, bool double_sided = false,
                     std::shared_ptr<const AlphaMask> mask = nullptr) {
  MeshPart p;
  p.first_index = 0;
  p.index_count = uint32_t(m.indices.size());
  p.role = role;
  p.material = material;
  p.double_sided = double_sided;
  p.mask = std::move(mask);
  m.parts = {p};
}

/// Flips every triangle whose normal points towards `inside(centroid)` so faces point outwards.
template <typename InsideFn>
void orient_outward(Mesh& m, InsideFn inside) {
  for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
    const Vec3f& a = m.positions[m.indices[t]];
    const Vec3f& b = m.positions[m.indices[t + 1]];
    const Vec3f& c = m.positions[m.indices[t + 2]];
    const Vec3f centroid = (a + b + c) / 3.0f;
    const Vec3f n = (b - a).cross(c - a);
    if (n.dot(centroid - inside(centroid)) < 0.0f) std::swap(m.indices[t + 1], m.indices[t + 2]);
  }
}

/// Quad p0-p1-p2-p3 (counter-clockwise seen from its front) with uvs (0,0),(1,0),(1,1),(0,1).
inline Mesh make_quad(const Vec3f& p0, const Vec3f& p1, const Vec3f& p2, const Vec3f& p3, Role role,
                      bool double_sided = false, std::shared_ptr<const AlphaMask> mask = nullptr) {
  Mesh m;
  m.positions = {p0, p1, p2, p3};
  m.uvs = {Vec2f(0, 0), Vec2f(1, 0), Vec2f(1, 1), Vec2f(0, 1)};
  m.indices = {0, 1, 2, 0, 2, 3};
  m.compute_normals();
  one_part(m, role, Material::Ground, double_sided, std::move(mask));
  return m;
}

/// Heightfield over [x0, x0+n*step] x [y0, y0+n*step], faces up, height h(x, y).
template <typename HeightFn>
Mesh make_heightfield(float x0, float y0, int n, float step, HeightFn h, Role role = Role::Ground) {
  Mesh m;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const float x = x0 + float(i) * step, y = y0 + float(j) * step;
      m.positions.emplace_back(x, y, h(x, y));
      m.uvs.emplace_back(float(i), float(j));
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const uint32_t a = uint32_t(j * (n + 1) + i), b = a + 1, c = a + uint32_t(n + 1), d = c + 1;
      m.indices.insert(m.indices.end(), {a, b, d, a, d, c});
    }
  m.compute_normals();
  one_part(m, role, Material::Ground);
  return m;
}

/// Closed cylinder of radius r from z0 to z1 around the z axis with `seg` sides.
inline Mesh make_cylinder(float r, float z0, float z1, int seg, Role role) {
  Mesh m;
  for (int i = 0; i < seg; ++i) {
    const float a = 2.0f * std::numbers::pi_v<float> * float(i) / float(seg);
    m.positions.emplace_back(r * std::cos(a), r * std::sin(a), z0);
    m.positions.emplace_back(r * std::cos(a), r * std::sin(a), z1);
  }
  const uint32_t bottom = uint32_t(m.positions.size());
  m.positions.emplace_back(0.0f, 0.0f, z0);
  m.positions.emplace_back(0.0f, 0.0f, z1);
  for (int i = 0; i < seg; ++i) {
    const uint32_t a = uint32_t(2 * i), b = uint32_t(2 * ((i + 1) % seg));
    m.indices.insert(m.indices.end(), {a, b, b + 1, a, b + 1, a + 1, bottom, b, a, bottom + 1, a + 1, b + 1});
  }
  m.uvs.assign(m.positions.size(), Vec2f::Zero());
  const float zc = 0.5f * (z0 + z1);
  const auto on_cap = [&](const Vec3f& c) { return std::abs(c.z() - z0) < 1e-4f || std::abs(c.z() - z1) < 1e-4f; };
  orient_outward(m, [&](const Vec3f& c) { return on_cap(c) ? Vec3f(0, 0, zc) : Vec3f(0, 0, c.z()); });
  m.compute_normals();
  one_part(m, role, Material::BarkConifer);
  return m;
}

/// Closed cone of base radius r from z0 (base) to apex z1 with `seg` sides.
inline Mesh make_cone(float r, float z0, float z1, int seg, Role role) {
  Mesh m;
  for (int i = 0; i < seg; ++i) {
    const float a = 2.0f * std::numbers::pi_v<float> * float(i) / float(seg);
    m.positions.emplace_back(r * std::cos(a), r * std::sin(a), z0);
  }
  const uint32_t base = uint32_t(m.positions.size());
  m.positions.emplace_back(0.0f, 0.0f, z0);
  m.positions.emplace_back(0.0f, 0.0f, z1);
  for (int i = 0; i < seg; ++i) {
    const uint32_t a = uint32_t(i), b = uint32_t((i + 1) % seg);
    m.indices.insert(m.indices.end(), {a, b, base + 1, base, b, a});
  }
  m.uvs.assign(m.positions.size(), Vec2f::Zero());
  const Vec3f centre(0, 0, z0 + 0.25f * (z1 - z0));
  orient_outward(m, [&](const Vec3f&) { return centre; });
  m.compute_normals();
  one_part(m, role, Material::Needles);
  return m;
}

/// Icosphere of radius r (subdivided `levels` times) around the origin.
inline Mesh make_icosphere(float r, int levels, Role role) {
  const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
  std::vector<Vec3f> v = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                          {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  std::vector<uint32_t> f = {0, 11, 5, 0, 5, 1, 0, 1, 7, 0, 7, 10, 0, 10, 11, 1, 5, 9, 5, 11, 4, 11, 10, 2, 10, 7, 6,
                             7, 1, 8, 3, 9, 4, 3, 4, 2, 3, 2, 6, 3, 6, 8, 3, 8, 9, 4, 9, 5, 2, 4, 11, 6, 2, 10, 8, 6, 7,
                             9, 8, 1};
  for (int l = 0; l < levels; ++l) {
    std::vector<uint32_t> g;
    for (size_t k = 0; k < f.size(); k += 3) {
      const uint32_t a = f[k], b = f[k + 1], c = f[k + 2];
      const uint32_t ab = uint32_t(v.size()), bc = ab + 1, ca = ab + 2;
      v.push_back(0.5f * (v[a] + v[b]));
      v.push_back(0.5f * (v[b] + v[c]));
      v.push_back(0.5f * (v[c] + v[a]));
      g.insert(g.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
    }
    f = g;
  }
  Mesh m;
  for (auto& p : v) m.positions.push_back(p.normalized() * r);
  m.indices = f;
  m.uvs.assign(m.positions.size(), Vec2f::Zero());
  orient_outward(m, [](const Vec3f&) { return Vec3f::Zero(); });
  m.compute_normals();
  one_part(m, role, Material::Rock);
  return m;
}

/// Terrain height used by the forest scene.
inline float forest_height(float x, float y) { return 0.6f * std::sin(0.31f * x) * std::cos(0.23f * y) + 0.02f * x; }

/// Terrain patch + 6 trees (trunk + canopy, instanced) + 4 rocks, seen by `camera_out`.
inline OwnedScene forest_scene(Camera& camera_out, int width = 320, int height = 240) {
  OwnedScene s;
  const uint32_t terrain = s.add_mesh(make_heightfield(-5.0f, -20.0f, 40, 1.0f, forest_height));
  s.add_instance(terrain);
  const uint32_t trunk = s.add_mesh(make_cylinder(0.25f, -0.5f, 5.0f, 12, Role::TreeTrunk));
  const uint32_t canopy = s.add_mesh(make_cone(1.6f, 2.5f, 8.0f, 16, Role::TreeCanopy));
  const uint32_t rock = s.add_mesh(make_icosphere(0.6f, 1, Role::Obstacle));
  const float trees[6][3] = {{8, -3, 0.3f}, {12, 4, 1.1f}, {17, -6, 2.0f}, {22, 2, 0.7f}, {27, -1, 1.5f}, {6, 5, 2.5f}};
  uint32_t id = 1;
  for (const auto& t : trees) {
    const Vec3f p(t[0], t[1], forest_height(t[0], t[1]));
    const float scale = 0.8f + 0.1f * float(id);
    s.add_instance(trunk, place(p, t[2], scale), id, 100 + id);
    s.add_instance(canopy, place(p, t[2], scale), id, 100 + id);
    ++id;
  }
  const float rocks[4][2] = {{4, -1}, {6, 1.5f}, {10, 0.5f}, {14, -2}};
  for (const auto& r : rocks) {
    const Vec3f p(r[0], r[1], forest_height(r[0], r[1]) + 0.1f);
    s.add_instance(rock, place(p, 0.3f * float(id), 0.7f + 0.1f * float(id % 3)), id, 200 + id);
    ++id;
  }
  camera_out = Camera::from_fov(width, height, 90.0, 0.05, 150.0);
  camera_out.camera_to_world = pose_from_angles(Vec3d(0.0, 0.3, forest_height(0, 0.3f) + 1.6), 3.0, -6.0, 1.5);
  return s;
}

}  // namespace silva::render::test
