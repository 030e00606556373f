#include "assets/dead_wood.hpp"

#include <algorithm>

namespace silva::assets {

void truncate_branch(Skeleton& s, size_t i, float t) {
  Branch& b = s.branches[i];
  std::vector<TubeNode> kept;
  const size_t segs = b.nodes.size() - 1;
  for (size_t k = 0; k <= segs && float(k) < t * float(segs) - 0.2f; ++k) kept.push_back(b.nodes[k]);
  kept.push_back(point_along(b, t));
  b.nodes = std::move(kept);
  b.length *= t;
  std::vector<bool> gone(s.branches.size(), false);
  for (size_t k = i + 1; k < s.branches.size(); ++k) {
    const Branch& c = s.branches[k];
    gone[k] = c.parent >= 0 && (gone[size_t(c.parent)] || (size_t(c.parent) == i && c.parent_t > t));
  }
  std::vector<int> index(s.branches.size(), -1);
  std::vector<Branch> out;
  for (size_t k = 0; k < s.branches.size(); ++k) {
    if (gone[k]) continue;
    Branch c = std::move(s.branches[k]);
    if (c.parent >= 0) c.parent = index[size_t(c.parent)];
    if (size_t(k) != i && c.parent == index[i] && index[i] >= 0) c.parent_t /= t;
    index[k] = int(out.size());
    out.push_back(std::move(c));
  }
  s.branches = std::move(out);
}

Skeleton dead_skeleton(float length, float r0, float top, Rng& rng) {
  SkeletonParams p;
  p.height = length;
  p.base_radius = r0;
  p.shape = CrownShape::Conical;
  p.radius_power = 0.7f;
  p.levels = {{.children = 30, .start = 0.15f, .rotate = 140, .curve_var = 3.0f, .tip_radius = 0.05f, .segments = 8},
              {.children = 4, .start = 0.3f, .length = 0.18f, .length_var = 0.5f, .down = 100, .down_tip = 65,
               .down_var = 25, .rotate = 140, .curve_var = 18, .tropism = 0.1f, .tip_radius = 0.2f, .segments = 3},
              {.length = 0.4f, .length_var = 0.3f, .down = 50, .down_var = 20, .curve_var = 15, .tip_radius = 0.3f,
               .segments = 2}};
  Skeleton s = grow_skeleton(p, rng);
  if (top < 1.0f) truncate_branch(s, 0, top);
  for (size_t i = s.branches.size(); i-- > 1;)
    if (s.branches[i].level == 1 && rng.uniform() < 0.7f) truncate_branch(s, i, rng.range(0.1f, 0.6f));
  return s;
}

}  // namespace silva::assets
