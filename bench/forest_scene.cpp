/// @file Construction of the synthetic bench forest (see forest_scene.hpp).
#include "bench/forest_scene.hpp"

#include <cmath>
#include <numbers>
#include <random>

namespace silva::bench {

using render::Instance;
using render::MeshLods;

namespace {

/// Terrain height of the bench world.
float height_at(float x, float y) { return 1.2f * std::sin(0.05f * x) * std::cos(0.07f * y) + 0.3f * std::sin(0.31f * x + 0.2f * y); }

/// Sets one part over the whole index buffer.
void whole_part(Mesh& m, Role role, Material mat, bool double_sided = false, std::shared_ptr<const AlphaMask> mask = {}) {
  MeshPart p;
  p.index_count = uint32_t(m.indices.size());
  p.role = role;
  p.material = mat;
  p.double_sided = double_sided;
  p.mask = std::move(mask);
  m.parts = {p};
}

/// One 32 m terrain chunk at 0.5 m spacing (8192 triangles).
Mesh terrain_chunk(float x0, float y0) {
  Mesh m;
  const int n = 64;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const float x = x0 + 0.5f * float(i), y = y0 + 0.5f * float(j);
      m.positions.emplace_back(x, y, height_at(x, y));
      m.uvs.emplace_back(x, y);
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const uint32_t a = uint32_t(j * (n + 1) + i), b = a + 1, c = a + uint32_t(n + 1), d = c + 1;
      m.indices.insert(m.indices.end(), {a, b, d, a, d, c});
    }
  m.compute_normals();
  whole_part(m, Role::Ground, Material::Ground);
  return m;
}

/// A tree: a tapered trunk of `rings` x `seg` quads plus `cards` alpha-tested leaf cards.
Mesh tree_mesh(int variant, const std::shared_ptr<const AlphaMask>& mask) {
  std::mt19937 gen(1000u + uint32_t(variant));
  std::uniform_real_distribution<float> u01(0.0f, 1.0f);
  const float height = 8.0f + 3.0f * float(variant);
  Mesh trunk;
  const int seg = 16, rings = 24;
  for (int r = 0; r <= rings; ++r)
    for (int s = 0; s < seg; ++s) {
      const float a = 2.0f * std::numbers::pi_v<float> * float(s) / float(seg);
      const float z = height * float(r) / float(rings), rad = 0.3f * (1.0f - 0.8f * float(r) / float(rings));
      trunk.positions.emplace_back(rad * std::cos(a), rad * std::sin(a), z - 0.3f);
      trunk.uvs.emplace_back(float(s) / float(seg), z);
    }
  for (int r = 0; r < rings; ++r)
    for (int s = 0; s < seg; ++s) {
      const uint32_t a = uint32_t(r * seg + s), b = uint32_t(r * seg + (s + 1) % seg), c = a + uint32_t(seg),
                     d = b + uint32_t(seg);
      trunk.indices.insert(trunk.indices.end(), {a, b, d, a, d, c});
    }
  trunk.compute_normals();
  whole_part(trunk, Role::TreeTrunk, Material::BarkConifer);
  Mesh leaves;
  const int cards = 800 + 400 * variant;
  for (int k = 0; k < cards; ++k) {
    const float z = height * (0.35f + 0.65f * u01(gen));
    const float spread = 2.5f * (1.0f - (z / height) * 0.8f);
    const float a = 2.0f * std::numbers::pi_v<float> * u01(gen), r = spread * std::sqrt(u01(gen));
    const Vec3f c(r * std::cos(a), r * std::sin(a), z);
    const Vec3f t(std::cos(a + 1.3f), std::sin(a + 1.3f), 0.3f * u01(gen)), up(0.2f * u01(gen), 0.0f, 1.0f);
    const float h = 0.45f;
    const uint32_t base = uint32_t(leaves.positions.size());
    leaves.positions.insert(leaves.positions.end(), {c - h * t - h * up, c + h * t - h * up, c + h * t + h * up, c - h * t + h * up});
    leaves.uvs.insert(leaves.uvs.end(), {Vec2f(0, 0), Vec2f(1, 0), Vec2f(1, 1), Vec2f(0, 1)});
    leaves.indices.insert(leaves.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
  }
  leaves.compute_normals();
  whole_part(leaves, Role::TreeCanopy, Material::Needles, true, mask);
  trunk.append(leaves);
  return trunk;
}

/// Adds a single-LOD mesh to `w` and returns its index in the scene.
uint32_t add_mesh(ForestScene& w, Mesh m) {
  w.meshes.push_back(std::make_unique<Mesh>(std::move(m)));
  w.scene.meshes.emplace_back().lods = {w.meshes.back().get()};
  w.scene.meshes.back().compute_bounds();
  return uint32_t(w.scene.meshes.size() - 1);
}

}  // namespace

ForestScene::ForestScene() {
  auto mask = std::make_shared<AlphaMask>();
  mask->width = mask->height = 32;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      const float dx = (float(x) - 15.5f) / 16.0f, dy = (float(y) - 15.5f) / 16.0f;
      mask->alpha.push_back(dx * dx + dy * dy < 0.8f ? 255 : 0);
    }
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      Instance inst;
      inst.mesh = add_mesh(*this, terrain_chunk(-64.0f + 32.0f * float(i), -64.0f + 32.0f * float(j)));
      scene.instances.push_back(inst);
    }
  const uint32_t first_tree = uint32_t(scene.meshes.size());
  for (int v = 0; v < 3; ++v) add_mesh(*this, tree_mesh(v, mask));
  std::mt19937 gen(42);
  std::uniform_real_distribution<float> pos(-62.0f, 62.0f), yaw(0.0f, 6.283f), scale(0.8f, 1.2f);
  for (uint32_t k = 0; k < 300; ++k) {
    const float x = pos(gen), y = pos(gen);
    if (std::abs(y) < 1.5f && x > -5.0f && x < 8.0f) continue;  // keep the camera's spot clear
    Instance inst;
    const float s = scale(gen);
    inst.object_to_world.leftCols<3>() = Eigen::AngleAxisf(yaw(gen), Vec3f::UnitZ()).toRotationMatrix() * s;
    inst.object_to_world.col(3) = Vec3f(x, y, height_at(x, y));
    inst.mesh = first_tree + k % 3;
    inst.instance_id = k + 1;
    scene.instances.push_back(inst);
  }
  camera = Camera::from_fov(1920, 1080, 90.0, 0.05, 150.0);
  camera.camera_to_world = pose_from_angles(Vec3d(-40.0, 0.0, height_at(-40.0f, 0.0f) + 1.6), 0.0, -3.0, 0.0);
}

size_t ForestScene::triangle_count() const {
  size_t n = 0;
  for (const Instance& inst : scene.instances) n += scene.meshes[inst.mesh].lods[0]->indices.size() / 3;
  return n;
}

const ForestScene& forest_scene() {
  static const ForestScene w;
  return w;
}

}  // namespace silva::bench
