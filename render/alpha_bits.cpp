#include "render/alpha_bits.hpp"

#include <string>

#include "core/error.hpp"

namespace silva::render {

AlphaBits AlphaBits::of(const AlphaMask& mask) {
  const size_t texels = size_t(mask.width) * size_t(mask.height);
  if (mask.width < 1 || mask.height < 1 || mask.alpha.size() != texels)
    throw InputError("render scene: alpha mask of " + std::to_string(mask.width) + "x" + std::to_string(mask.height) +
                     " texels holds " + std::to_string(mask.alpha.size()) + " alpha values (needs width*height >= 1)");
  AlphaBits bits;
  bits.width = mask.width;
  bits.height = mask.height;
  bits.words.assign((texels + 31) / 32, 0u);
  for (size_t i = 0; i < texels; ++i)
    if (mask.opaque_texel(int(i))) bits.words[i / 32] |= 1u << (i % 32);
  return bits;
}

void AlphaBitsCache::update(const Scene& scene) {
  ++updates_;
  const auto add = [&](const Mesh& mesh) {
    for (const MeshPart& part : mesh.parts) {
      if (!part.mask) continue;
      auto it = entries_.find(part.mask.get());
      if (it == entries_.end()) it = entries_.emplace(part.mask.get(), Entry{part.mask, AlphaBits::of(*part.mask), 0}).first;
      it->second.used = updates_;
    }
  };
  for (const MeshLods& m : scene.meshes) {
    for (const Mesh* lod : m.lods) add(*lod);
    if (m.shadow_caster) add(*m.shadow_caster);
  }
  std::erase_if(entries_, [&](const auto& kv) { return kv.second.used != updates_; });
}

const AlphaBits* AlphaBitsCache::find(const AlphaMask* mask) const {
  const auto it = entries_.find(mask);
  return it == entries_.end() ? nullptr : &it->second.bits;
}

}  // namespace silva::render
