#include "assets/card_thinning.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace silva::assets {

namespace {

/// Root of vertex v in a union-find forest (path halving).
uint32_t find_root(std::vector<uint32_t>& parent, uint32_t v) {
  while (parent[v] != v) v = parent[v] = parent[parent[v]];
  return v;
}

}  // namespace

std::vector<uint32_t> thin_cards(const Mesh& mesh, const MeshPart& part, float ratio, std::vector<Vec3f>& positions) {
  const uint32_t* idx = mesh.indices.data() + part.first_index;
  std::vector<uint32_t> whole(idx, idx + part.index_count);  // returned (moved) when nothing is thinned
  // Vertices used outside this part must not move.
  std::vector<uint8_t> elsewhere(mesh.positions.size(), 0);
  for (size_t i = 0; i < mesh.indices.size(); ++i)
    if (i < part.first_index || i >= size_t(part.first_index) + part.index_count) elsewhere[mesh.indices[i]] = 1;
  std::vector<uint32_t> parent(mesh.positions.size());
  std::iota(parent.begin(), parent.end(), 0u);
  for (uint32_t t = 0; t + 2 < part.index_count; t += 3) {
    if (elsewhere[idx[t]] || elsewhere[idx[t + 1]] || elsewhere[idx[t + 2]]) return whole;
    const uint32_t a = find_root(parent, idx[t]);
    for (int k = 1; k < 3; ++k) {
      const uint32_t b = find_root(parent, idx[t + k]);
      if (b != a) parent[b] = a;
    }
  }
  // Cards numbered in the order of their first triangle.
  std::vector<uint32_t> card_of_root(mesh.positions.size(), UINT32_MAX);
  std::vector<uint32_t> card_of_triangle(part.index_count / 3);
  uint32_t cards = 0;
  for (uint32_t t = 0; t < part.index_count / 3; ++t) {
    uint32_t& c = card_of_root[find_root(parent, idx[3 * t])];
    if (c == UINT32_MAX) c = cards++;
    card_of_triangle[t] = c;
  }
  const uint32_t kept = std::clamp(uint32_t(std::lround(double(cards) * double(ratio))), 1u, std::max(cards, 1u));
  if (cards == 0 || kept >= cards) return whole;
  // Card c is kept when the running count floor((c + 1) * kept / cards) steps up at c.
  const auto keeps = [&](uint64_t c) { return (c + 1) * kept / cards != c * kept / cards; };
  // Each kept card's centre: the mean of its distinct vertices.
  std::vector<Vec3f> centre(cards, Vec3f::Zero());
  std::vector<uint32_t> vertex_count(cards, 0);
  std::vector<uint8_t> seen(mesh.positions.size(), 0);
  for (uint32_t i = 0; i < part.index_count; ++i) {
    const uint32_t v = idx[i];
    if (seen[v]) continue;
    seen[v] = 1;
    const uint32_t c = card_of_triangle[i / 3];
    centre[c] += mesh.positions[v];
    ++vertex_count[c];
  }
  const float grow = float(std::sqrt(double(cards) / double(kept)));
  std::vector<uint32_t> out;
  std::fill(seen.begin(), seen.end(), 0);
  for (uint32_t t = 0; t < part.index_count / 3; ++t) {
    const uint32_t c = card_of_triangle[t];
    if (!keeps(c)) continue;
    const Vec3f mid = centre[c] / float(vertex_count[c]);
    for (int k = 0; k < 3; ++k) {
      const uint32_t v = idx[3 * t + uint32_t(k)];
      out.push_back(v);
      if (!seen[v]) positions[v] = mid + grow * (mesh.positions[v] - mid);
      seen[v] = 1;
    }
  }
  return out;
}

Mesh with_thinned_cards(const Mesh& mesh, float ratio) {
  std::vector<Vec3f> positions = mesh.positions;
  std::vector<std::vector<uint32_t>> part_indices;
  for (const MeshPart& part : mesh.parts) {
    const auto first = mesh.indices.begin() + part.first_index;
    part_indices.push_back(part.mask ? thin_cards(mesh, part, ratio, positions)
                                     : std::vector<uint32_t>(first, first + part.index_count));
  }
  return compact_mesh(mesh, positions, part_indices);
}

}  // namespace silva::assets
