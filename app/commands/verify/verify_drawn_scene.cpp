// `silva verify`'s scene of the geometry as drawn (see verify_drawn_scene.hpp).
#include "app/commands/verify/verify_drawn_scene.hpp"

#include "render/instance_cull.hpp"
#include "render/view_projection.hpp"

namespace silva::app {

std::vector<raycast::RayInstance> drawn_instances(const systems::FrameScene& frame, const Camera& camera) {
  const render::Scene& scene = frame.scene;
  std::vector<render::BoundingSphere> spheres;
  render::mesh_spheres(scene, spheres);
  render::InstanceSelection selection;
  render::select_instances(scene, render::ViewProjection::from_camera(camera), spheres, true, selection);
  std::vector<raycast::RayInstance> out;
  out.reserve(selection.order.size());
  for (size_t i = 0; i < scene.instances.size(); ++i) {
    if (selection.lod[i] == render::kCulled) continue;
    const render::Instance& inst = scene.instances[i];
    out.push_back({&scene.meshes[inst.mesh].level(selection.lod[i]), inst.object_to_world, inst.instance_id});
  }
  return out;
}

void DrawnRayScene::show(systems::FrameScene frame, const Camera& camera) {
  const uint64_t next = key_ ^ 1u;
  scene_->add_group(next, drawn_instances(frame, camera));  // before the old group goes: shared BVHs stay built
  scene_->remove_group(key_);
  scene_->commit();
  frame_ = std::move(frame);
  key_ = next;
}

}  // namespace silva::app
