#include "app/commands/world/world_export.hpp"

#include <algorithm>

#include "world/collision_proxy.hpp"

namespace silva::app {

namespace {
/// A placed object with its chunk order (stable tie-break for stuff, whose instance id is 0).
struct ObjectRef {
  const Vegetation* object;
  size_t order;
};

std::string chunk_name(const char* what, ChunkCoord c) {
  return std::string(what) + "_" + std::to_string(c.i) + "_" + std::to_string(c.j);
}
}  // namespace

io::GltfDocument world_document(const BuiltWorld& world, const assets::AssetLibrary& library, const Ontology& ontology,
                                bool instancing) {
  io::GltfDocument doc;
  io::GltfNode root;
  root.name = "silva_world";
  root.matrix = io::z_up_to_y_up();
  doc.nodes.push_back(root);
  doc.roots.push_back(0);
  auto add_node = [&](io::GltfNode node) {
    doc.nodes.push_back(std::move(node));
    doc.nodes[0].children.push_back(uint32_t(doc.nodes.size() - 1));
  };
  auto add_world_mesh = [&](const Mesh& mesh, const std::string& name, Role role) {
    if (mesh.indices.empty()) return;
    doc.meshes.push_back({name, &mesh, {}});
    io::GltfNode node;
    node.name = name;
    node.mesh = int(doc.meshes.size() - 1);
    node.extras = {{"class_id", ontology.id(role)}, {"instance_id", 0}};
    if (mesh.parts[0].overlay) node.extras["overlay_class_id"] = ontology.id(mesh.parts[0].overlay->role);
    add_node(std::move(node));
  };
  for (const ChunkContent& c : world.chunks) add_world_mesh(c.terrain, chunk_name("terrain", c.coord), Role::Ground);

  // Asset meshes are shared: mesh index = first asset mesh + asset index.
  const int first_asset_mesh = int(doc.meshes.size());
  for (const assets::Asset& a : library.assets)
    doc.meshes.push_back({a.name, &a.lods()[0], io::part_class_extras(a.lods()[0], a.role, ontology)});

  std::vector<ObjectRef> objects;
  for (const ChunkContent& c : world.chunks)
    for (const Vegetation& v : c.objects) objects.push_back({&v, objects.size()});
  std::stable_sort(objects.begin(), objects.end(), [](const ObjectRef& a, const ObjectRef& b) {
    // Things by instance id first, then stuff (id 0) in chunk order.
    const uint64_t ka = a.object->instance_id ? a.object->instance_id : (uint64_t(1) << 32) + a.order;
    const uint64_t kb = b.object->instance_id ? b.object->instance_id : (uint64_t(1) << 32) + b.order;
    return ka < kb;
  });
  if (instancing) {
    std::vector<io::GltfNode> per_asset(library.assets.size());
    for (const ObjectRef& ref : objects) {
      const Vegetation& v = *ref.object;
      per_asset[v.asset].instances.push_back(
          {world::object_to_world(v.position, v.yaw, v.scale), ontology.id(v.role), v.instance_id});
    }
    for (size_t a = 0; a < per_asset.size(); ++a) {
      if (per_asset[a].instances.empty()) continue;
      per_asset[a].name = library.assets[a].name;
      per_asset[a].mesh = first_asset_mesh + int(a);
      add_node(std::move(per_asset[a]));
    }
  } else {
    for (const ObjectRef& ref : objects) {
      const Vegetation& v = *ref.object;
      io::GltfNode node;
      node.name = library.assets[v.asset].name;
      node.mesh = first_asset_mesh + int(v.asset);
      node.matrix = io::to_matrix(world::object_to_world(v.position, v.yaw, v.scale));
      node.extras = {{"class_id", ontology.id(v.role)}, {"instance_id", v.instance_id}};
      add_node(std::move(node));
    }
  }
  return doc;
}

}  // namespace silva::app
