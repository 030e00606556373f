#include "app/commands/asset_files.hpp"

#include "assets/manifest.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"

namespace silva::app {

using assets::Asset;
using assets::AssetLibrary;
using assets::ManifestEntry;

io::GltfDocument asset_document(const Asset& asset) {
  io::GltfDocument doc;
  io::GltfNode root;
  root.name = asset.name;
  root.matrix = io::z_up_to_y_up();
  root.extras = {{"class", role_name(asset.role)}, {"kind", assets::kind_name(asset.kind)}};
  doc.nodes.push_back(root);
  doc.roots = {0};
  for (size_t k = 0; k < asset.lods.size(); ++k) {
    const std::string name = "lod" + std::to_string(k);
    io::GltfMesh mesh{name, &asset.lods[k], {}};
    for (const MeshPart& part : asset.lods[k].parts) mesh.part_extras.push_back({{"role", role_name(part.role)}});
    doc.meshes.push_back(std::move(mesh));
    io::GltfNode node;
    node.name = name;
    node.mesh = int(k);
    doc.nodes.push_back(std::move(node));
    doc.nodes[0].children.push_back(uint32_t(k + 1));
  }
  return doc;
}

AssetLibrary build_library(const std::filesystem::path& out_dir, uint64_t seed) {
  std::error_code ec;
  std::filesystem::create_directories(out_dir, ec);
  if (ec) throw IoError("cannot create " + out_dir.string() + ": " + ec.message());
  AssetLibrary lib = assets::generate_library(seed);
  std::vector<ManifestEntry> entries;
  for (const Asset& a : lib.assets) {
    io::write_glb(asset_document(a), out_dir / a.file);
    entries.push_back(assets::manifest_entry(a));
  }
  io::write_file_atomic(out_dir / "library.json", assets::manifest_text(entries));
  return lib;
}

}  // namespace silva::app
