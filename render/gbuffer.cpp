#include "render/gbuffer.hpp"

namespace silva::render {

void GBuffer::resize(int w, int h) {
  width = w;
  height = h;
  const size_t n = size();
  depth.assign(n, 0.0f);
  position.assign(n, Vec3f::Zero());
  normal.assign(n, Vec3f::Zero());
  uv.assign(n, Vec2f::Zero());
  role.assign(n, Role::Background);
  material.assign(n, Material::Ground);
  base_color.assign(n, 0);
  instance_id.assign(n, 0);
  variation.assign(n, 0);
  leaf.assign(n, 0);
  mask_texels.assign(n, 0.0f);
}

}  // namespace silva::render
