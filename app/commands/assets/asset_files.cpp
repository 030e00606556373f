#include "app/commands/assets/asset_files.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <utility>

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
  const std::vector<Mesh>& lods = asset.lods();
  for (size_t k = 0; k < lods.size(); ++k) {
    const std::string name = "lod" + std::to_string(k);
    io::GltfMesh mesh{name, &lods[k], {}};
    for (const MeshPart& part : lods[k].parts) mesh.part_extras.push_back({{"role", role_name(part.role)}});
    doc.meshes.push_back(std::move(mesh));
    io::GltfNode node;
    node.name = name;
    node.mesh = int(k);
    doc.nodes.push_back(std::move(node));
    doc.nodes[0].children.push_back(uint32_t(k + 1));
  }
  return doc;
}

AssetLibrary build_library(const std::filesystem::path& out_dir, bool glb, uint64_t seed, uint32_t max_variants) {
  std::error_code ec;
  std::filesystem::create_directories(out_dir, ec);
  if (ec) throw IoError("cannot create " + out_dir.string() + ": " + ec.message());
  std::vector<std::pair<const assets::Factory*, uint32_t>> variants;
  for (const assets::Factory& f : assets::factories())
    for (uint32_t v = 0; v < std::min(f.variants, max_variants); ++v) variants.emplace_back(&f, v);
  AssetLibrary lib;
  lib.assets.resize(variants.size());
  tbb::parallel_for(size_t(0), variants.size(), [&](size_t i) {
    lib.assets[i] = assets::make_asset(*variants[i].first, seed, variants[i].second);
  });
  lib.index_kinds();
  std::vector<ManifestEntry> entries;
  for (Asset& a : lib.assets) {
    if (glb) {
      a.file = a.name + ".glb";
      io::write_glb(asset_document(a), out_dir / a.file);
    }
    entries.push_back(assets::manifest_entry(a));
  }
  io::write_file_atomic(out_dir / "library.json", assets::manifest_text(entries));
  return lib;
}

}  // namespace silva::app
