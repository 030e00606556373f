#include "assets/mesh_builder.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>

namespace silva::assets {

void MeshBuilder::begin_part(Role role, Material material, std::shared_ptr<const AlphaMask> mask,
                             bool double_sided) {
  MeshPart part;
  part.first_index = uint32_t(mesh_.indices.size());
  part.role = role;
  part.material = material;
  part.mask = std::move(mask);
  part.double_sided = double_sided;
  mesh_.parts.push_back(std::move(part));
}

uint32_t MeshBuilder::vertex(const Vec3f& p, const Vec3f& n, const Vec2f& uv) {
  mesh_.positions.push_back(p);
  mesh_.normals.push_back(n.normalized());
  mesh_.uvs.push_back(uv);
  return uint32_t(mesh_.positions.size() - 1);
}

void MeshBuilder::triangle(uint32_t a, uint32_t b, uint32_t c) {
  mesh_.indices.insert(mesh_.indices.end(), {a, b, c});
  mesh_.parts.back().index_count += 3;
}

Mesh MeshBuilder::finish() {
  std::erase_if(mesh_.parts, [](const MeshPart& p) { return p.index_count == 0; });
  return std::move(mesh_);
}

void perpendicular_frame(const Vec3f& axis, Vec3f& u, Vec3f& v) {
  const Vec3f helper = std::abs(axis.z()) < 0.9f ? Vec3f::UnitZ() : Vec3f::UnitX();
  u = helper.cross(axis).normalized();
  v = axis.cross(u);
}

float TubeLobes::ridge(float a) const {
  if (count == 0) return 0.0f;
  const float c = std::max(0.0f, std::cos(float(count) * (a - phase)));
  return c * c * c * c;
}

void add_tube(MeshBuilder& b, std::span<const TubeNode> nodes, int segments, float v_height, const TubeLobes& lobes,
              std::vector<Vec3f>* end_ring) {
  const size_t n = nodes.size();
  const float step = 2.0f * std::numbers::pi_v<float> / float(segments);  // angle between ring points
  std::vector<uint32_t> prev_ring, ring;
  Vec3f u, v;
  float length = 0;
  for (size_t i = 0; i < n; ++i) {
    const size_t lo = i == 0 ? 0 : i - 1, hi = i + 1 == n ? i : i + 1;
    const Vec3f span = nodes[hi].p - nodes[lo].p;
    const Vec3f t = span.normalized();
    const float slope = (nodes[lo].r - nodes[hi].r) / span.norm();
    if (i == 0) {
      perpendicular_frame(t, u, v);
    } else {
      length += (nodes[i].p - nodes[i - 1].p).norm();
      u = (u - t * t.dot(u)).normalized();  // carry the frame along (rotation-minimising)
      v = t.cross(u);
    }
    ring.clear();
    const float tex_v = v_height > 0 ? nodes[i].p.z() / v_height : 0.5f * length;
    for (int k = 0; k <= segments; ++k) {
      const float a = 2.0f * std::numbers::pi_v<float> * float(k % segments) / float(segments);
      const Vec3f radial = std::cos(a) * u + std::sin(a) * v;
      if (nodes[i].lobe == 0.0f) {
        ring.push_back(b.vertex(nodes[i].p + nodes[i].r * radial, radial + slope * t,
                                Vec2f(float(k) / float(segments), tex_v)));
        continue;
      }
      // r(a) = r (1 + lobe ridge(a)); the normal is square to the chord between the neighbouring
      // points around the ring, so it follows the sampled ridges (a ridge's analytic slope, between
      // samples, could face away from the triangles drawn).
      const auto lobed = [&](float angle) {
        return nodes[i].r * (1.0f + nodes[i].lobe * lobes.ridge(angle)) * (std::cos(angle) * u + std::sin(angle) * v);
      };
      const Vec3f chord = lobed(a + step) - lobed(a - step);
      ring.push_back(b.vertex(nodes[i].p + lobed(a), chord.cross(t).normalized() + slope * t,
                              Vec2f(float(k) / float(segments), tex_v)));
    }
    if (i > 0)
      for (int k = 0; k < segments; ++k) {
        b.triangle(prev_ring[size_t(k)], prev_ring[size_t(k) + 1], ring[size_t(k) + 1]);
        b.triangle(prev_ring[size_t(k)], ring[size_t(k) + 1], ring[size_t(k)]);
      }
    std::swap(prev_ring, ring);
  }
  if (end_ring)
    for (int k = 0; k < segments; ++k) end_ring->push_back(b.position(prev_ring[size_t(k)]));
}

void add_disc(MeshBuilder& b, const Vec3f& center, const Vec3f& normal, float radius, int segments) {
  Vec3f u, v;
  perpendicular_frame(normal.normalized(), u, v);
  const uint32_t c = b.vertex(center, normal, Vec2f(0.5f, 0.5f));
  std::vector<uint32_t> ring;
  for (int k = 0; k < segments; ++k) {
    const float a = 2.0f * std::numbers::pi_v<float> * float(k) / float(segments);
    const float ca = std::cos(a), sa = std::sin(a);
    ring.push_back(b.vertex(center + radius * (ca * u + sa * v), normal, Vec2f(0.5f + 0.5f * ca, 0.5f + 0.5f * sa)));
  }
  for (int k = 0; k < segments; ++k) b.triangle(c, ring[size_t(k)], ring[size_t((k + 1) % segments)]);
}

void add_card(MeshBuilder& b, const Vec3f& center, const Vec3f& right, const Vec3f& up) {
  const Vec3f n = right.cross(up);
  const uint32_t tl = b.vertex(center - right + up, n, Vec2f(0, 0));
  const uint32_t tr = b.vertex(center + right + up, n, Vec2f(1, 0));
  const uint32_t br = b.vertex(center + right - up, n, Vec2f(1, 1));
  const uint32_t bl = b.vertex(center - right - up, n, Vec2f(0, 1));
  b.triangle(bl, br, tr);
  b.triangle(bl, tr, tl);
}

Mesh unit_icosphere(int subdivisions) {
  const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
  std::vector<Vec3f> pos = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                            {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  std::vector<uint32_t> idx = {0, 11, 5, 0, 5, 1, 0, 1, 7, 0, 7, 10, 0, 10, 11, 1, 5, 9, 5, 11, 4,
                               11, 10, 2, 10, 7, 6, 7, 1, 8, 3, 9, 4, 3, 4, 2, 3, 2, 6, 3, 6, 8,
                               3, 8, 9, 4, 9, 5, 2, 4, 11, 6, 2, 10, 8, 6, 7, 9, 8, 1};
  for (auto& p : pos) p.normalize();
  for (int s = 0; s < subdivisions; ++s) {
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> midpoints;
    auto mid = [&](uint32_t a, uint32_t b) {
      const auto key = std::minmax(a, b);
      auto [it, inserted] = midpoints.try_emplace(key, uint32_t(pos.size()));
      if (inserted) pos.push_back((pos[a] + pos[b]).normalized());
      return it->second;
    };
    std::vector<uint32_t> next;
    for (size_t f = 0; f < idx.size(); f += 3) {
      const uint32_t a = idx[f], b = idx[f + 1], c = idx[f + 2];
      const uint32_t ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
      next.insert(next.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
    }
    idx = std::move(next);
  }
  Mesh m;
  m.positions = pos;
  m.normals = pos;
  for (const auto& p : pos) m.uvs.emplace_back(0.5f + 0.5f * p.x(), 0.5f + 0.5f * p.y());
  m.indices = std::move(idx);
  return m;
}

}  // namespace silva::assets
