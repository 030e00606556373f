#include "assets/root_flare.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <numbers>

#include "core/rng.hpp"

namespace silva::assets {

float flare_fraction(const Branch& trunk) { return std::min(0.04f, 0.5f / std::max(trunk.length, 1.0f)); }

float buttress_lobe(Material bark) {
  switch (bark) {
    case Material::BarkBeech:
    case Material::BarkOak: return 0.45f;
    case Material::BarkSpruce:
    case Material::BarkLarch:
    case Material::BarkDead:
    case Material::BarkConifer: return 0.3f;
    default: return 0.18f;
  }
}

void add_root_flare(MeshBuilder& b, const Branch& trunk, Material bark, float v_height) {
  if (trunk.nodes.size() < 2) return;
  const uint64_t h = mix64(uint64_t(std::bit_cast<uint32_t>(trunk.length)) << 32 |
                           std::bit_cast<uint32_t>(trunk.nodes.front().r));
  const TubeLobes lobes{4 + int(h % 4), float(h >> 8 & 0xffff) / 65536.0f * 2.0f * std::numbers::pi_v<float>};
  const float lobe = buttress_lobe(bark);
  const TubeNode base = trunk.nodes.front(), top = point_along(trunk, flare_fraction(trunk));
  const Vec3f axis = (top.p - base.p).normalized();
  const float foot = kFlareFoot * base.r;
  const std::array<TubeNode, 4> nodes = {{
      {base.p - 0.2f * axis, foot, lobe},
      {base.p, foot, lobe},
      {base.p + 0.45f * (top.p - base.p), 1.04f * (0.55f * foot + 0.45f * top.r), 0.45f * lobe},
      {top.p, 1.02f * top.r, 0.0f},
  }};
  add_tube(b, nodes, std::clamp(4 * lobes.count, 16, 28), v_height, lobes);
}

}  // namespace silva::assets
