#include "world/terrain.hpp"

#include <cmath>
#include <vector>

#include "core/rng.hpp"

namespace silva::world {

namespace {

/// Height of the function at global vertex-grid index (gx, gy).
double grid_height(const TerrainField& f, int64_t gx, int64_t gy) {
  return f.max_elevation * fbm2(f.noise, double(gx) * f.vertex_spacing, double(gy) * f.vertex_spacing);
}

/// Unit normal from heights one spacing to each side (central differences).
Vec3f normal_from_differences(double h_left, double h_right, double h_down, double h_up, double spacing) {
  const double dx = (h_right - h_left) / (2.0 * spacing);
  const double dy = (h_up - h_down) / (2.0 * spacing);
  const double len = std::sqrt(dx * dx + dy * dy + 1.0);
  return Vec3f(float(-dx / len), float(-dy / len), float(1.0 / len));
}

}  // namespace

TerrainField make_terrain_field(const Config& cfg) {
  TerrainField f;
  f.noise.octaves = cfg.terrain.octaves;
  f.noise.lacunarity = cfg.terrain.lacunarity;
  f.noise.persistence = cfg.terrain.persistence;
  f.noise.frequency = cfg.terrain.frequency;
  Rng rng(uint64_t(cfg.seed), 0, Purpose::TerrainOffset);
  f.noise.offset_x = rng.uniform_double() * 4096.0 - 2048.0;
  f.noise.offset_y = rng.uniform_double() * 4096.0 - 2048.0;
  f.max_elevation = cfg.terrain.max_elevation;
  f.vertex_spacing = cfg.terrain.vertex_spacing;
  return f;
}

float terrain_height(const TerrainField& field, double x, double y) {
  return float(field.max_elevation * fbm2(field.noise, x, y));
}

float surface_height(const TerrainField& field, double x, double y) {
  const double gxf = std::floor(x / field.vertex_spacing);
  const double gyf = std::floor(y / field.vertex_spacing);
  const double fx = x / field.vertex_spacing - gxf;
  const double fy = y / field.vertex_spacing - gyf;
  const int64_t gx = int64_t(gxf), gy = int64_t(gyf);
  // Heights as stored in the mesh (float), so the surface matches the triangles exactly.
  const double h00 = float(grid_height(field, gx, gy));
  const double h11 = float(grid_height(field, gx + 1, gy + 1));
  // Each cell is split along its (0,0)-(1,1) diagonal, as in build_terrain_mesh.
  if (fx >= fy) {
    const double h10 = float(grid_height(field, gx + 1, gy));
    return float(h00 + fx * (h10 - h00) + fy * (h11 - h10));
  }
  const double h01 = float(grid_height(field, gx, gy + 1));
  return float(h00 + fy * (h01 - h00) + fx * (h11 - h01));
}

Vec3f terrain_normal(const TerrainField& field, double x, double y) {
  const double d = field.vertex_spacing;
  return normal_from_differences(field.max_elevation * fbm2(field.noise, x - d, y),
                                 field.max_elevation * fbm2(field.noise, x + d, y),
                                 field.max_elevation * fbm2(field.noise, x, y - d),
                                 field.max_elevation * fbm2(field.noise, x, y + d), d);
}

Mesh build_terrain_mesh(const TerrainField& field, double chunk_size, ChunkCoord coord) {
  const int n = int(std::lround(chunk_size / field.vertex_spacing));
  const int side = n + 3;  // one extra ring of samples for the central differences
  const int64_t gx0 = int64_t(coord.i) * n - 1, gy0 = int64_t(coord.j) * n - 1;
  std::vector<double> h(size_t(side) * side);
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x) h[size_t(y) * side + x] = grid_height(field, gx0 + x, gy0 + y);
  auto at = [&](int x, int y) { return h[size_t(y + 1) * side + (x + 1)]; };

  Mesh m;
  const size_t verts = size_t(n + 1) * (n + 1);
  m.positions.reserve(verts);
  m.normals.reserve(verts);
  m.uvs.reserve(verts);
  for (int y = 0; y <= n; ++y) {
    for (int x = 0; x <= n; ++x) {
      const double wx = double(gx0 + 1 + x) * field.vertex_spacing;
      const double wy = double(gy0 + 1 + y) * field.vertex_spacing;
      m.positions.emplace_back(float(wx), float(wy), float(at(x, y)));
      m.normals.push_back(normal_from_differences(at(x - 1, y), at(x + 1, y), at(x, y - 1), at(x, y + 1),
                                                  field.vertex_spacing));
      m.uvs.emplace_back(float(wx / kGroundUvMetres), float(wy / kGroundUvMetres));
    }
  }
  m.indices.reserve(size_t(n) * n * 6);
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      const uint32_t v00 = uint32_t(y * (n + 1) + x), v10 = v00 + 1;
      const uint32_t v01 = v00 + uint32_t(n + 1), v11 = v01 + 1;
      m.indices.insert(m.indices.end(), {v00, v10, v11, v00, v11, v01});
    }
  }
  MeshPart part;
  part.index_count = uint32_t(m.indices.size());
  part.role = Role::Ground;
  part.material = Material::Ground;
  m.parts.push_back(part);
  return m;
}

}  // namespace silva::world
