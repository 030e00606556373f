#include "world/terrain.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/rng.hpp"
#include "world/noise_lanes.hpp"

namespace silva::world {

namespace {

/// Natural (unshaped) height of the function at world (x, y).
double natural_height(const TerrainField& f, double x, double y) { return f.max_elevation * fbm2(f.noise, x, y); }

/// Height of the function where the natural height is `natural` and the nearest trail point `p`.
double shaped(const TerrainField& f, const TrailPoint& p, double natural) {
  return f.trail ? shaped_height(*f.trail, p, natural) : natural;
}

/// Nearest trail point of world (x, y) (none without a trail).
TrailPoint trail_point(const TerrainField& f, double x, double y) {
  return f.trail ? nearest_trail_point(*f.trail, x, y) : TrailPoint{};
}

/// Height of the function at world (x, y).
double height_at(const TerrainField& f, double x, double y) {
  return shaped(f, trail_point(f, x, y), natural_height(f, x, y));
}

/// heights[k] = height_at(f, x[k], y[k]) for k < n, the natural heights n at a time on SIMD lanes.
void heights_at(const TerrainField& f, const double* x, const double* y, double* heights, size_t n) {
  fbm2_lanes(f.noise, x, y, heights, n);
  for (size_t k = 0; k < n; ++k) heights[k] = shaped(f, trail_point(f, x[k], y[k]), f.max_elevation * heights[k]);
}

/// World coordinate of global vertex-grid index g.
double grid_coordinate(const TerrainField& f, int64_t g) { return double(g) * f.vertex_spacing; }

/// Terrain uv of a point whose nearest trail point is `p`: (distance to the trail edge, at most
/// the shoulder; arc length along the trail where a centre-line point is near, else 0).
Vec2f trail_uv(const TerrainField& f, const TrailPoint& p) {
  if (!f.trail) return Vec2f(float(kTrailShoulder), 0.0f);
  const double d = std::min(p.distance, f.trail->reach());
  return Vec2f(float(d - f.trail->half_width), std::isfinite(p.distance) ? float(p.along) : 0.0f);
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
  if (cfg.trail.enabled)
    f.trail = std::make_shared<const TrailPath>(
        make_trail_path(cfg, [&f](double x, double y) { return natural_height(f, x, y); }));
  return f;
}

float terrain_height(const TerrainField& field, double x, double y) { return float(height_at(field, x, y)); }

void terrain_heights(const TerrainField& field, const double* x, const double* y, float* heights, size_t n) {
  std::vector<double> h(n);
  heights_at(field, x, y, h.data(), n);
  for (size_t k = 0; k < n; ++k) heights[k] = float(h[k]);
}

float surface_height(const TerrainField& field, double x, double y) {
  const double gxf = std::floor(x / field.vertex_spacing);
  const double gyf = std::floor(y / field.vertex_spacing);
  const double fx = x / field.vertex_spacing - gxf;
  const double fy = y / field.vertex_spacing - gyf;
  const int64_t gx = int64_t(gxf), gy = int64_t(gyf);
  // Heights as stored in the mesh (float), so the surface matches the triangles exactly. Each cell is
  // split along its (0,0)-(1,1) diagonal, as in build_terrain_mesh: corners (0,0), (1,1) and the third.
  const bool lower = fx >= fy;
  const double cx[3] = {grid_coordinate(field, gx), grid_coordinate(field, gx + 1),
                         grid_coordinate(field, lower ? gx + 1 : gx)};
  const double cy[3] = {grid_coordinate(field, gy), grid_coordinate(field, gy + 1),
                         grid_coordinate(field, lower ? gy : gy + 1)};
  double h[3];
  heights_at(field, cx, cy, h, 3);
  const double h00 = float(h[0]), h11 = float(h[1]), third = float(h[2]);
  if (lower) return float(h00 + fx * (third - h00) + fy * (h11 - third));
  return float(h00 + fy * (third - h00) + fx * (h11 - third));
}

Vec3f terrain_normal(const TerrainField& field, double x, double y) {
  const double d = field.vertex_spacing;
  const double xs[4] = {x - d, x + d, x, x}, ys[4] = {y, y, y - d, y + d};
  double h[4];
  heights_at(field, xs, ys, h, 4);
  return normal_from_differences(h[0], h[1], h[2], h[3], d);
}

Mesh build_terrain_mesh(const TerrainField& field, double chunk_size, ChunkCoord coord) {
  const int n = int(std::lround(chunk_size / field.vertex_spacing));
  const int side = n + 3;  // one extra ring of samples for the central differences
  const int64_t gx0 = int64_t(coord.i) * n - 1, gy0 = int64_t(coord.j) * n - 1;
  std::vector<double> h(size_t(side) * side);
  std::vector<Vec2f> uv(size_t(side) * side);
  std::vector<double> row_x(size_t(side), 0.0), row_y(size_t(side), 0.0);
  bool trail_near = false;
  for (int y = 0; y < side; ++y) {
    for (int x = 0; x < side; ++x) {
      row_x[size_t(x)] = grid_coordinate(field, gx0 + x);
      row_y[size_t(x)] = grid_coordinate(field, gy0 + y);
    }
    double* row = h.data() + size_t(y) * side;
    fbm2_lanes(field.noise, row_x.data(), row_y.data(), row, size_t(side));
    for (int x = 0; x < side; ++x) {
      const TrailPoint p = trail_point(field, row_x[size_t(x)], row_y[size_t(x)]);
      row[x] = shaped(field, p, field.max_elevation * row[x]);
      uv[size_t(y) * side + x] = trail_uv(field, p);
      trail_near = trail_near || (field.trail && p.distance < field.trail->reach());
    }
  }
  auto at = [&](int x, int y) { return h[size_t(y + 1) * side + (x + 1)]; };

  Mesh m;
  const size_t verts = size_t(n + 1) * (n + 1);
  m.positions.reserve(verts);
  m.normals.reserve(verts);
  m.uvs.reserve(verts);
  for (int y = 0; y <= n; ++y) {
    for (int x = 0; x <= n; ++x) {
      const double wx = grid_coordinate(field, gx0 + 1 + x);
      const double wy = grid_coordinate(field, gy0 + 1 + y);
      m.positions.emplace_back(float(wx), float(wy), float(at(x, y)));
      m.normals.push_back(normal_from_differences(at(x - 1, y), at(x + 1, y), at(x, y - 1), at(x, y + 1),
                                                  field.vertex_spacing));
      m.uvs.push_back(uv[size_t(y + 1) * side + (x + 1)]);
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
  if (trail_near) part.overlay = PartOverlay{Role::Trail, Material::Trail};
  m.parts.push_back(part);
  return m;
}

}  // namespace silva::world
