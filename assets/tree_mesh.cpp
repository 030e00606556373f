#include "assets/tree_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "assets/root_flare.hpp"
#include "assets/wood_parts.hpp"

namespace silva::assets {

namespace {

/// Sides of a tube of base radius r: few for thin branches.
int tube_sides(float r) { return r > 0.15f ? 12 : r > 0.06f ? 8 : r > 0.03f ? 6 : 4; }

/// The part of a branch at least kMinTubeRadius thick (cut where the radius reaches it); the
/// trunk gets a root flare. Fewer than 2 nodes: no tube.
std::vector<TubeNode> tube_nodes(const Branch& br) {
  std::vector<TubeNode> out;
  for (size_t i = 0; i < br.nodes.size(); ++i) {
    const TubeNode& n = br.nodes[i];
    if (n.r >= kMinTubeRadius) {
      out.push_back(n);
      continue;
    }
    if (i > 0 && br.nodes[i - 1].r > kMinTubeRadius) {  // end where the radius reaches the minimum
      const TubeNode& a = br.nodes[i - 1];
      const float f = (a.r - kMinTubeRadius) / (a.r - n.r);
      if (f * (n.p - a.p).norm() > 0.05f) out.push_back({a.p + f * (n.p - a.p), kMinTubeRadius});
    }
    break;
  }
  if (br.level == 0 && out.size() >= 2) {
    const TubeNode flare_top = point_along(br, flare_fraction(br));
    out.insert(out.begin() + 1, flare_top);
    out[0].r *= kFlareFoot;
  }
  return out;
}

/// Fraction along a branch from which it carries cards: [start, 1] for foliage levels, else
/// its non-tube tail (radius below kMinTubeRadius; the trunk's leader), or nothing (returns > 1).
float card_from(const Branch& br, const FoliageParams& f) {
  if (br.level >= f.level) return f.start;
  const float r0 = br.nodes.front().r, r1 = br.nodes.back().r;
  if (r1 >= kMinTubeRadius) return 2.0f;
  return r0 <= kMinTubeRadius ? 0.0f : (r0 - kMinTubeRadius) / (r0 - r1);
}

/// One card on a twig at point p with twig direction d.
void add_twig_card(MeshBuilder& b, const Skeleton& s, const FoliageParams& f, Rng& rng, const Vec3f& p,
                   const Vec3f& d, float enlarge) {
  const float h = f.half * enlarge * rng.range(0.8f, 1.2f);
  Vec3f centre, right, up;
  if (f.style == CardStyle::Spray) {
    up = (d - f.droop * Vec3f::UnitZ()).normalized();
    Vec3f side, other;
    perpendicular_frame(up, side, other);
    const float roll = rng.range(-0.5f, 0.5f);
    right = std::cos(roll) * side + std::sin(roll) * other;
    centre = p + 0.9f * h * up;
  } else {
    const Vec3f flat(d.x(), d.y(), 0);
    const Vec3f out = flat.norm() > 1e-3f ? Vec3f(flat.normalized()) : Vec3f::Zero();
    Vec3f n = out + Vec3f(0, 0, 0.7f) + 0.8f * random_direction(rng);
    n = n.norm() > 1e-3f ? Vec3f(n.normalized()) : Vec3f::UnitZ();
    Vec3f u, v;
    perpendicular_frame(n, u, v);
    const float spin = rng.range(0.0f, 2.0f * std::numbers::pi_v<float>);
    right = std::cos(spin) * u + std::sin(spin) * v;
    up = n.cross(right);
    centre = p + 0.35f * h * random_direction(rng);
  }
  if (inside_trunk(s, centre)) return;
  add_card(b, centre, h * right, h * up);
}

}  // namespace

bool inside_trunk(const Skeleton& s, const Vec3f& p) {
  const auto& n = s.branches.front().nodes;
  for (size_t i = 1; i < n.size(); ++i) {
    const Vec3f ab = n[i].p - n[i - 1].p;
    const float t = std::clamp((p - n[i - 1].p).dot(ab) / ab.squaredNorm(), 0.0f, 1.0f);
    const float r = n[i - 1].r + t * (n[i].r - n[i - 1].r);
    if ((p - (n[i - 1].p + t * ab)).norm() < 1.3f * r) return true;  // 1.3: the root flare
  }
  return false;
}

CollisionProxy trunk_proxy(const Skeleton& s) {
  const Branch& trunk = s.branches.front();
  const std::vector<TubeNode> tube = tube_nodes(trunk);
  const float top = tube.size() >= 2 ? tube.back().p.z() : trunk.nodes.back().p.z();
  const float breast = trunk.length > 2.6f ? 1.3f / trunk.length : 0.0f;
  return cylinder_proxy(point_along(trunk, breast).r, top);
}

namespace {

/// A broken-off branch's end: its tube's last ring and the direction out of the wood.
struct StubEnd {
  std::vector<Vec3f> ring;  ///< The tube's last ring, counter-clockwise about axis.
  Vec3f axis;               ///< Unit direction of the tube's last segment.
};

/// Range of a stub's splinters' reach, in stub radii along its axis (add_end_cap's jag).
constexpr float kStubJag[2] = {0.5f, 1.5f};

/// Adds the cards `f` along the branches of `s`, within what kTreeTriangleBudget leaves after
/// `tube_triangles`.
void add_cards(MeshBuilder& b, const Skeleton& s, const FoliageParams& f, int tube_triangles, Rng& rng) {
  float total = 0;
  for (const Branch& br : s.branches) total += std::max(0.0f, 1.0f - card_from(br, f)) * br.length;
  // Card counts per branch are rounded stochastically (unbiased): 100 cards of slack cover that.
  const int budget = std::min(f.max_cards, (kTreeTriangleBudget - tube_triangles) / 2 - 100);
  const float spacing = std::max(f.spacing, total / float(std::max(1, budget)));
  // Fewer cards than the species' spacing asks for: each grows so the crown keeps its cover.
  const float enlarge = std::min(2.0f, std::sqrt(spacing / f.spacing));
  b.begin_part(f.role, f.material, f.family ? f.family(2.0f * f.half * enlarge) : f.mask, true);
  for (const Branch& br : s.branches) {
    const float from = card_from(br, f);
    if (from >= 1.0f) continue;
    const float span = (1.0f - from) * br.length;
    const int cards = int(span / spacing + rng.uniform());
    for (int k = 0; k < cards; ++k) {
      const float t = from + (1.0f - from) * (float(k) + rng.range(0.2f, 0.8f)) / float(cards);
      const float dt = 0.5f / float(br.nodes.size());
      const Vec3f d = point_along(br, std::min(1.0f, t + dt)).p - point_along(br, std::max(0.0f, t - dt)).p;
      add_twig_card(b, s, f, rng, point_along(br, t).p, d.normalized(), enlarge);
    }
  }
}

}  // namespace

void mesh_tree(MeshBuilder& b, const Skeleton& s, const TreeLook& look, Rng& rng) {
  float height = 0.1f;
  for (const Branch& br : s.branches)
    for (const TubeNode& n : br.nodes) height = std::max(height, n.p.z());
  b.begin_part(look.bark_role, look.bark);
  int tube_triangles = 0;
  bool trunk_tube = false;
  std::vector<StubEnd> stubs;
  for (const Branch& br : s.branches) {
    const std::vector<TubeNode> tube = tube_nodes(br);
    if (tube.size() < 2) continue;
    const bool stub = look.torn_ends && br.level > 0 && tube.back().r > kMinTubeRadius;
    if (stub) stubs.push_back({{}, (tube.back().p - tube[tube.size() - 2].p).normalized()});
    add_tube(b, tube, tube_sides(tube.front().r), height, {}, stub ? &stubs.back().ring : nullptr);
    tube_triangles += 2 * tube_sides(tube.front().r) * int(tube.size() - 1);
    trunk_tube = trunk_tube || &br == &s.branches.front();
  }
  if (trunk_tube) add_root_flare(b, s.branches.front(), look.bark, height);  // on top of the budget: at most 168 triangles
  if (look.foliage) add_cards(b, s, look.cards, tube_triangles, rng);
  if (stubs.empty()) return;
  b.begin_part(look.bark_role, Material::BrokenWood);
  for (const StubEnd& end : stubs) add_end_cap(b, rng, end.ring, end.axis, rng.range(kStubJag[0], kStubJag[1]));
}

}  // namespace silva::assets
