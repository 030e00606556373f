#include "assets/load_library.hpp"

#include "assets/factory.hpp"
#include "assets/import_mesh.hpp"
#include "assets/lod.hpp"
#include "assets/manifest.hpp"
#include "core/error.hpp"

namespace silva::assets {

namespace {

/// Every built-in generator name, comma-separated (for error messages).
std::string generator_names() {
  std::string out;
  for (const Factory& f : factories()) out += std::string(out.empty() ? "" : ", ") + f.prefix;
  return out;
}

/// A generator entry: its metadata now, its meshes when first drawn.
Asset procedural_entry(const ManifestEntry& e, const std::string& where, Season season) {
  const Factory* factory = find_factory(e.source->generator);
  if (!factory)
    throw InputError(where + ".generator '" + e.source->generator + "' is not a built-in generator (" +
                     generator_names() + ")");
  if (factory->kind != e.kind)
    throw InputError(where + ".kind " + kind_name(e.kind) + " does not match generator " + factory->prefix + " (" +
                     kind_name(factory->kind) + ")");
  Asset a = lazy_asset(*factory, e.source->seed, e.source->variant, e.role, e.proxy, e.lod_screen_sizes, season);
  a.name = e.name;
  return a;
}

/// A file entry: its meshes imported through assimp now (LODs built when the file has one level).
Asset file_entry(const ManifestEntry& e, const std::filesystem::path& folder, const std::string& where) {
  Asset a;
  a.name = e.name;
  a.file = e.file;
  a.kind = e.kind;
  a.role = e.role;
  a.proxy = e.proxy;
  std::vector<Mesh> lods = import_asset_lods(folder / e.file, e.parts, e.z_up, where);
  a.lod_screen_sizes = e.lod_screen_sizes;
  if (lods.size() == 1 && !e.lod_screen_sizes.empty()) {
    LodChain chain = build_lods(lods[0], e.lod_screen_sizes);
    lods = std::move(chain.lods);
    a.lod_screen_sizes = std::move(chain.screen_sizes);
  }
  a.lod_screen_sizes.resize(std::min(a.lod_screen_sizes.size(), lods.size() - 1));
  lods.resize(a.lod_screen_sizes.size() + 1);
  a.geometry = std::make_shared<const AssetGeometry>(std::move(lods));
  return a;
}

}  // namespace

AssetLibrary load_library(const std::filesystem::path& library_json, Season season) {
  const std::vector<ManifestEntry> entries = read_manifest(library_json);
  AssetLibrary lib;
  for (size_t i = 0; i < entries.size(); ++i) {
    const std::string where = library_json.string() + " assets[" + std::to_string(i) + "]";
    lib.assets.push_back(entries[i].source ? procedural_entry(entries[i], where, season)
                                           : file_entry(entries[i], library_json.parent_path(), where));
  }
  lib.index_kinds();
  return lib;
}

}  // namespace silva::assets
