#include "core/mesh.hpp"

#include <cmath>

namespace silva {

AABB Mesh::bounds() const {
  AABB b;
  for (const auto& p : positions) b.extend(p);
  return b;
}

void Mesh::compute_normals() {
  normals.assign(positions.size(), Vec3f::Zero());
  for (size_t t = 0; t + 2 < indices.size(); t += 3) {
    const uint32_t a = indices[t], b = indices[t + 1], c = indices[t + 2];
    const Vec3f n = (positions[b] - positions[a]).cross(positions[c] - positions[a]);
    normals[a] += n;
    normals[b] += n;
    normals[c] += n;
  }
  for (auto& n : normals) {
    const float len = n.norm();
    n = len > 0 ? Vec3f(n / len) : Vec3f(0, 0, 1);
  }
}

void Mesh::append(const Mesh& other) {
  const uint32_t base = uint32_t(positions.size());
  const uint32_t index_base = uint32_t(indices.size());
  positions.insert(positions.end(), other.positions.begin(), other.positions.end());
  normals.insert(normals.end(), other.normals.begin(), other.normals.end());
  uvs.insert(uvs.end(), other.uvs.begin(), other.uvs.end());
  for (uint32_t i : other.indices) indices.push_back(i + base);
  for (MeshPart p : other.parts) {
    p.first_index += index_base;
    parts.push_back(p);
  }
}

Mesh compact_mesh(const Mesh& source, const std::vector<Vec3f>& positions,
                  const std::vector<std::vector<uint32_t>>& part_indices) {
  std::vector<uint32_t> remap(positions.size(), UINT32_MAX);
  for (const auto& idx : part_indices)
    for (uint32_t i : idx) remap[i] = 0;
  Mesh out;
  for (size_t v = 0; v < remap.size(); ++v) {
    if (remap[v] == UINT32_MAX) continue;
    remap[v] = uint32_t(out.positions.size());
    out.positions.push_back(positions[v]);
    out.normals.push_back(source.normals[v]);
    out.uvs.push_back(source.uvs[v]);
  }
  for (size_t p = 0; p < source.parts.size(); ++p) {
    MeshPart part = source.parts[p];
    part.first_index = uint32_t(out.indices.size());
    part.index_count = uint32_t(part_indices[p].size());
    for (uint32_t i : part_indices[p]) out.indices.push_back(remap[i]);
    out.parts.push_back(std::move(part));
  }
  return out;
}

}  // namespace silva
