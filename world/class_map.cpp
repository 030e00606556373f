#include "world/class_map.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace silva::world {

namespace {

/// What an asset looks like from above: the reach of its mesh around its origin and the class
/// and height of its highest part.
struct TopView {
  float radius = 0;       ///< Largest horizontal distance of a vertex from the origin (m, scale 1).
  float top = 0;          ///< Highest vertex z (m, scale 1).
  Role role = Role::Obstacle;  ///< Role of the part holding the highest vertex.
};

/// Top view of one asset's coarsest LOD.
TopView top_view(const assets::Asset& asset) {
  TopView v;
  v.role = asset.role;
  if (asset.lods().empty()) return v;
  const Mesh& m = asset.lods().back();
  for (const Vec3f& p : m.positions) v.radius = std::max(v.radius, std::hypot(p.x(), p.y()));
  v.top = -std::numeric_limits<float>::infinity();
  for (const MeshPart& part : m.parts)
    for (uint32_t k = part.first_index; k < part.first_index + part.index_count; ++k) {
      const float z = m.positions[m.indices[k]].z();
      if (z > v.top) {
        v.top = z;
        v.role = part.role;
      }
    }
  return v;
}

/// Pixel writer over a ClassMap.
class Canvas {
 public:
  Canvas(ClassMap& map, const Ontology& ontology) : map_(map), ontology_(ontology) {}
  /// Fills every pixel whose centre lies in the disc (cx, cy, r); at least the centre pixel.
  void disc(double cx, double cy, double r, Role role) {
    const double u = (cx - map_.x0) / map_.metres_per_pixel, v = (map_.y1 - cy) / map_.metres_per_pixel;
    const double rp = r / map_.metres_per_pixel;
    const int u0 = int(std::floor(u - rp)), u1 = int(std::floor(u + rp)), v0 = int(std::floor(v - rp)),
              v1 = int(std::floor(v + rp));
    put(int(std::floor(u)), int(std::floor(v)), role);
    for (int y = v0; y <= v1; ++y)
      for (int x = u0; x <= u1; ++x) {
        const double dx = x + 0.5 - u, dy = y + 0.5 - v;
        if (dx * dx + dy * dy <= rp * rp) put(x, y, role);
      }
  }
  /// Fills every pixel whose centre lies in the triangle's horizontal projection.
  void triangle(const Vec3f& a, const Vec3f& b, const Vec3f& c, Role role) {
    const double p[3][2] = {{(a.x() - map_.x0) / map_.metres_per_pixel, (map_.y1 - a.y()) / map_.metres_per_pixel},
                            {(b.x() - map_.x0) / map_.metres_per_pixel, (map_.y1 - b.y()) / map_.metres_per_pixel},
                            {(c.x() - map_.x0) / map_.metres_per_pixel, (map_.y1 - c.y()) / map_.metres_per_pixel}};
    auto edge = [](const double* s, const double* e, double x, double y) {
      return (e[0] - s[0]) * (y - s[1]) - (e[1] - s[1]) * (x - s[0]);
    };
    const double area = edge(p[0], p[1], p[2][0], p[2][1]);
    if (area == 0) return;
    const int x0 = int(std::floor(std::min({p[0][0], p[1][0], p[2][0]})));
    const int x1 = int(std::ceil(std::max({p[0][0], p[1][0], p[2][0]})));
    const int y0 = int(std::floor(std::min({p[0][1], p[1][1], p[2][1]})));
    const int y1 = int(std::ceil(std::max({p[0][1], p[1][1], p[2][1]})));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const double cx = x + 0.5, cy = y + 0.5;
        const double w0 = edge(p[1], p[2], cx, cy), w1 = edge(p[2], p[0], cx, cy), w2 = edge(p[0], p[1], cx, cy);
        const bool inside = area > 0 ? (w0 >= 0 && w1 >= 0 && w2 >= 0) : (w0 <= 0 && w1 <= 0 && w2 <= 0);
        if (inside) put(x, y, role);
      }
  }

 private:
  void put(int x, int y, Role role) {
    if (x < 0 || y < 0 || x >= map_.width || y >= map_.height) return;
    const auto& c = ontology_.color(role);
    std::copy(c.begin(), c.end(), map_.rgb.begin() + (size_t(y) * map_.width + x) * 3);
  }

  ClassMap& map_;
  const Ontology& ontology_;
};

}  // namespace

ClassMap render_class_map(const BuiltWorld& world, double chunk_size, const assets::AssetLibrary& library,
                          const Ontology& ontology, double metres_per_pixel) {
  ClassMap map;
  map.metres_per_pixel = metres_per_pixel;
  if (world.chunks.empty()) return map;
  int i0 = world.chunks.front().coord.i, i1 = i0, j0 = world.chunks.front().coord.j, j1 = j0;
  for (const ChunkContent& c : world.chunks) {
    i0 = std::min(i0, c.coord.i), i1 = std::max(i1, c.coord.i);
    j0 = std::min(j0, c.coord.j), j1 = std::max(j1, c.coord.j);
  }
  const double s = chunk_size;
  map.x0 = i0 * s;
  map.y1 = (j1 + 1) * s;
  map.width = int(std::ceil((i1 + 1 - i0) * s / metres_per_pixel));
  map.height = int(std::ceil((j1 + 1 - j0) * s / metres_per_pixel));
  map.rgb.assign(size_t(map.width) * map.height * 3, 0);
  const auto& bg = ontology.color(Role::Background);
  for (size_t k = 0; k < map.rgb.size(); k += 3) std::copy(bg.begin(), bg.end(), map.rgb.begin() + k);
  Canvas canvas(map, ontology);
  for (const ChunkContent& c : world.chunks) {
    const Vec3f lo(c.coord.i * s, c.coord.j * s, 0), hi((c.coord.i + 1) * s, (c.coord.j + 1) * s, 0);
    canvas.triangle(lo, Vec3f(hi.x(), lo.y(), 0), hi, Role::Ground);
    canvas.triangle(lo, hi, Vec3f(lo.x(), hi.y(), 0), Role::Ground);
  }
  std::vector<TopView> views;
  for (const assets::Asset& a : library.assets) views.push_back(top_view(a));
  // Lowest tops first, so canopies cover shrubs and shrubs cover grass; ties keep world order.
  std::vector<const Vegetation*> objects;
  for (const ChunkContent& c : world.chunks)
    for (const Vegetation& v : c.objects) objects.push_back(&v);
  std::stable_sort(objects.begin(), objects.end(), [&](const Vegetation* a, const Vegetation* b) {
    return views[a->asset].top * a->scale < views[b->asset].top * b->scale;
  });
  for (const Vegetation* v : objects) {
    const TopView& t = views[v->asset];
    canvas.disc(v->position.x(), v->position.y(), t.radius * v->scale, t.role);
  }
  // Plan overlays: the trail over the canopy, then every solid's footprint in its own class.
  for (const ChunkContent& c : world.chunks)
    for (size_t k = 0; k + 2 < c.trail.indices.size(); k += 3)
      canvas.triangle(c.trail.positions[c.trail.indices[k]], c.trail.positions[c.trail.indices[k + 1]],
                      c.trail.positions[c.trail.indices[k + 2]], Role::Trail);
  for (const Vegetation* v : objects) {
    const assets::Asset& a = library.assets[v->asset];
    if (a.proxy.shape == assets::CollisionProxy::Shape::None) continue;
    canvas.disc(v->position.x(), v->position.y(), a.proxy.footprint_radius() * v->scale, a.role);
  }
  return map;
}

}  // namespace silva::world
