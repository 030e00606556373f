#include "render/mask_cache.hpp"

namespace silva::render {

void MaskCache::update(const Scene& scene) {
  ++updates_;
  const auto add = [&](const Mesh& mesh) {
    for (const MeshPart& part : mesh.parts) {
      if (!part.mask) continue;
      auto it = entries_.find(part.mask.get());
      if (it == entries_.end())
        it = entries_.emplace(part.mask.get(), Entry{part.mask, AlphaBits::of(*part.mask), LeafMips::of(*part.mask), 0})
                 .first;
      it->second.used = updates_;
    }
  };
  for (const MeshLods& m : scene.meshes) {
    for (const Mesh* lod : m.lods) add(*lod);
    if (m.shadow_caster) add(*m.shadow_caster);
  }
  std::erase_if(entries_, [&](const auto& kv) { return kv.second.used != updates_; });
}

const MaskCache::Entry* MaskCache::entry(const AlphaMask* mask) const {
  const auto it = entries_.find(mask);
  return it == entries_.end() ? nullptr : &it->second;
}

const AlphaBits* MaskCache::find(const AlphaMask* mask) const {
  const Entry* e = entry(mask);
  return e ? &e->bits : nullptr;
}

const LeafMips* MaskCache::leaf_mips(const AlphaMask* mask) const {
  const Entry* e = entry(mask);
  return e ? &e->mips : nullptr;
}

}  // namespace silva::render
