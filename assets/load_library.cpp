#include "assets/load_library.hpp"

#include "assets/import_mesh.hpp"
#include "assets/lod.hpp"
#include "assets/manifest.hpp"

namespace silva::assets {

AssetLibrary load_library(const std::filesystem::path& library_json) {
  const std::vector<ManifestEntry> entries = read_manifest(library_json);
  AssetLibrary lib;
  for (size_t i = 0; i < entries.size(); ++i) {
    const ManifestEntry& e = entries[i];
    Asset a;
    a.name = e.name;
    a.file = e.file;
    a.kind = e.kind;
    a.role = e.role;
    a.proxy = e.proxy;
    a.lods = import_asset_lods(library_json.parent_path() / e.file, e.parts, e.z_up,
                               library_json.string() + " assets[" + std::to_string(i) + "]");
    a.lod_screen_sizes = e.lod_screen_sizes;
    if (a.lods.size() == 1 && !e.lod_screen_sizes.empty()) {
      LodChain chain = build_lods(a.lods[0], e.lod_screen_sizes);
      a.lods = std::move(chain.lods);
      a.lod_screen_sizes = std::move(chain.screen_sizes);
    }
    a.lod_screen_sizes.resize(std::min(a.lod_screen_sizes.size(), a.lods.size() - 1));
    a.lods.resize(a.lod_screen_sizes.size() + 1);
    lib.assets.push_back(std::move(a));
  }
  lib.index_kinds();
  return lib;
}

}  // namespace silva::assets
